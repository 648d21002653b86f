#include "framework/runtime/constrained_stage.h"

#include <cmath>
#include <limits>
#include <memory>

#include "framework/core/error.h"
#include "framework/runtime/positioning_stage.h"

namespace fitfeel {
namespace {

struct ConstrainedState final : StageState {
  // Where the last settled tick left the part (the next settle's starting point), and its slope.
  SettleMemory settle;
  // The law's state (friction junctions), advanced once per tick at the rendered pose.
  LawState law;
  // The god object's part and its balances (Options::proxy_stiffness finite).
  GodObjectMemory god;
};

}  // namespace

ConstrainedStage::ConstrainedStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law)
    : ConstrainedStage(analyzer, law, Options{}) {}

ConstrainedStage::ConstrainedStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law,
                                   const Options& options)
    : options_(options),
      search_(analyzer, law),
      settle_(search_),
      god_object_(search_, options.proxy_stiffness) {
  if (!analyzer.prepared()) throw UserError("constrained stage needs a prepared contact analyzer");
  if (!std::isfinite(options.depth_origin) || !(options.proxy_stiffness > 0.0)) {
    throw UserError(
        "constrained stage: the depth origin must be finite and the proxy stiffness > 0");
  }
}

std::unique_ptr<StageState> ConstrainedStage::DoMakeState() const {
  return std::make_unique<ConstrainedState>();
}

void ConstrainedStage::DoEvaluate(const PartState& part, StageState* state,
                                  StageOutput* out) const noexcept {
  if (options_.moving == Role::kInner) {
    EvaluateInAnalyzerFrame(part, state, out);
    return;
  }
  // The reflection in z (AnalyzerPose) of every vector read and written; the twist stays, so the
  // orientation does too.
  const Eigen::Vector3d reflect(1.0, 1.0, -1.0);
  PartState relative = part;
  relative.position = part.position.cwiseProduct(reflect);
  relative.velocity = part.velocity.cwiseProduct(reflect);
  relative.angular_velocity = part.angular_velocity.cwiseProduct(reflect);
  relative.settle_load.y() = -part.settle_load.y();
  out->pose = AnalyzerPose(out->pose, options_.moving);  // the hand-over's
  EvaluateInAnalyzerFrame(relative, state, out);
  out->pose = AnalyzerPose(out->pose, options_.moving);
  out->wrench.force = out->wrench.force.cwiseProduct(reflect);
  out->wrench.torque = out->wrench.torque.cwiseProduct(reflect);
  out->gap_direction.y() = -out->gap_direction.y();
  SceneContact(&out->contact, options_.moving);
}

void ConstrainedStage::EvaluateInAnalyzerFrame(const PartState& part, StageState* state,
                                               StageOutput* out) const noexcept {
  auto* run = static_cast<ConstrainedState*>(state);
  // Handed over by the positioning stage: the part is where that stage left it.
  if (out->stage != StageId::kConstrained) {
    run->god.part = out->pose.offset;
    run->god.part_depth = out->pose.depth;
  }
  out->pose = MatingPoseOf(part);
  out->pose.depth -= options_.depth_origin;
  out->contact = ContactState{};
  out->elastic = ElasticLimitCheck{};
  MatingMotion motion;
  motion.velocity = part.velocity;
  motion.angular_velocity = part.angular_velocity;
  motion.depth = out->pose.depth;
  motion.angle = out->pose.angle;
  const bool settle = part.settle_load.squaredNorm() > 0.0;
  if (!settle && std::isfinite(options_.proxy_stiffness)) {
    god_object_.FollowDevice(motion, &run->god, &run->law, out);
    return;
  }
  out->wrench.SetZero();
  out->next = out->pose.depth < 0.0 ? StageId::kPositioning : StageId::kConstrained;
  // The settle starts where the last one left the part, not at the device's pose: the contact
  // there is evaluated only when nothing carries the load.
  if (settle && settle_.Settle(part.settle_load, motion, &run->settle, &run->law, out)) {
    // Settled: nothing integrates the part's radial motion, so neither stiffness nor gap is needed.
    out->stiffness = 0.0;
    out->gap = std::numeric_limits<double>::infinity();
    out->gap_direction.setZero();
    return;
  }
  search_.analyzer().Evaluate(out->pose, &out->contact);
  ++out->contact_evaluations;
  // Out of engagement (withdrawn, about to hand back to positioning) the junctions let go, so a
  // later re-entry forms its contact afresh rather than at a stale anchor.
  if (!out->contact.engaged) run->law = LawState{};
  search_.law().Evaluate(out->contact, motion, &run->law, &out->wrench);
  out->elastic = search_.law().CheckElasticLimit(out->contact);
  out->stiffness =
      search_.RadialStiffness(out->pose, motion, out->wrench, &out->contact_evaluations);
  SetGap(out);
}

}  // namespace fitfeel
