#include "framework/device/device.h"

#include <cmath>
#include <memory>

#include "framework/core/demand.h"
#include "framework/core/error.h"
#include "framework/device/stage.h"

namespace fitfeel {

Device::~Device() = default;
Stage::~Stage() = default;

std::string_view ToString(StageId stage) {
  switch (stage) {
    case StageId::kPositioning: return "positioning";
    case StageId::kConstrained: return "constrained";
  }
  return "unknown";
}

void Device::Configure(const ConfigNode& node) { DoConfigure(node); }

void Device::Start(double period) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw UserError("device tick period must be a positive number of seconds");
  }
  DoStart(period);
}

void Device::Stop() noexcept { DoStop(); }

void Device::Read(double time, DeviceState* out) noexcept {
  FITFEEL_DEMAND(out != nullptr);
  DoRead(time, out);
}

void Device::Write(const Wrench& wrench) noexcept {
  // The safety chain guarantees finite wrenches; a device must never see anything else.
  if (!wrench.AllFinite()) {
    DoWrite(Wrench{});
    return;
  }
  DoWrite(wrench);
}

void Device::RunServoLoop(double, const std::function<bool(double)>&) {
  throw UnsupportedError("this device does not own a servo clock; run it from the scheduler");
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

void Stage::Evaluate(const DeviceState& device, StageState* state,
                     StageOutput* out) const noexcept {
  FITFEEL_DEMAND(out != nullptr);
  FITFEEL_DEMAND(state != nullptr && state->owner() == this);
  out->contact_evaluations = 0;
  DoEvaluate(device, state, out);
  out->stage = id();
}

}  // namespace fitfeel
