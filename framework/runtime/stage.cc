#include "framework/runtime/stage.h"

#include <memory>

#include "framework/core/demand.h"

namespace fitfeel {

Stage::~Stage() = default;

std::string_view ToString(StageId stage) {
  switch (stage) {
    case StageId::kPositioning:
      return "positioning";
    case StageId::kConstrained:
      return "constrained";
  }
  return "unknown";
}

StageState::~StageState() = default;

namespace {
// A stage that keeps nothing between ticks.
class EmptyStageState final : public StageState {};
}  // namespace

std::unique_ptr<StageState> Stage::MakeState() const {
  std::unique_ptr<StageState> state = DoMakeState();
  FITFEEL_DEMAND(state != nullptr);
  state->owner_ = this;
  return state;
}

std::unique_ptr<StageState> Stage::DoMakeState() const {
  return std::make_unique<EmptyStageState>();
}

void Stage::Evaluate(const PartState& part, StageState* state, StageOutput* out) const noexcept {
  FITFEEL_DEMAND(out != nullptr);
  FITFEEL_DEMAND(state != nullptr && state->owner() == this);
  out->contact_evaluations = 0;
  // Only a joint of several features writes its features' forces; every other tick has none.
  out->feature_count = 0;
  out->feature_axial.fill(0.0);
  out->screw = ScrewOutput{};
  DoEvaluate(part, state, out);
  out->stage = id();
}

}  // namespace fitfeel
