#include "framework/runtime/screw_stage.h"

#include <cmath>
#include <memory>

#include "framework/core/demand.h"
#include "framework/core/error.h"
#include "framework/runtime/part_state.h"

namespace fitfeel {

struct ScrewStage::RunState final : StageState {
  bool started = false;
  double time = 0.0;
  double depth = 0.0, angle = 0.0;
  // d(axial force)/d(depth) where the last settle ended (N/m, < 0), for the next tick's first step.
  double slope = 0.0;
  LawState law;
  ScrewOutput screw;
};

ScrewStage::ScrewStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law,
                       const Options& options)
    : analyzer_(analyzer), law_(law), options_(options) {
  if (!analyzer.prepared()) throw UserError("screw stage needs a prepared contact analyzer");
  if (!std::isfinite(options.depth_origin) || !(options.proxy_stiffness > 0.0) ||
      !std::isfinite(options.axial_load) || !(options.turn.speed >= 0.0)) {
    throw UserError("screw stage: the depth origin, axial load and turning speed must be finite "
                    "and the proxy stiffness > 0");
  }
}

std::unique_ptr<StageState> ScrewStage::DoMakeState() const {
  return std::make_unique<RunState>();
}

double ScrewStage::AxialForce(double depth, double angle, const LawState& law,
                              StageOutput* out) const noexcept {
  MatingPose pose;
  pose.depth = depth;
  pose.angle = angle;
  analyzer_.Evaluate(pose, &out->contact);
  ++out->contact_evaluations;
  MatingMotion motion;
  motion.depth = depth;
  motion.angle = angle;
  LawState trial = law;
  Wrench wrench;
  law_.Evaluate(out->contact, motion, &trial, &wrench);
  return wrench.force.y();
}

double ScrewStage::SettleDepth(double angle, double device_depth, RunState* run,
                               StageOutput* out) const noexcept {
  const double k = options_.proxy_stiffness;
  const bool hand = std::isfinite(k);
  // The balance g(z) = contact + load falls with z: the contact pushes back harder the further
  // the part advances, and so does the hand's spring.
  auto balance = [&](double z) {
    const double load = hand ? k * (device_depth - z) : options_.axial_load;
    return AxialForce(z, angle, run->law, out) + load;
  };
  double z0 = run->depth, g0 = balance(z0);
  // Within a thousandth of a newton, or of a millionth of the spring's pull: the settle's error
  // is below what any device renders.
  auto settled = [&](double g) { return std::abs(g) <= 1e-3; };
  if (settled(g0)) return z0;
  const double slope0 = hand ? -k : 0.0;
  double slope = run->slope < 0.0 ? run->slope : slope0;
  // Until a root is bracketed: Newton on the last slope, or a step that doubles where the balance
  // is flat (the part crossing its flanks' play).
  double step = slope < 0.0 ? -g0 / slope : std::copysign(1e-6, g0);
  double lo = 0.0, hi = 0.0, g_lo = 0.0, g_hi = 0.0;
  bool bracketed = false;
  int evaluations = 1;
  while (evaluations < kMaxEvaluations) {
    const double z1 = z0 + step, g1 = balance(z1);
    ++evaluations;
    if (settled(g1)) {
      if (z1 != z0 && g1 != g0) run->slope = (g1 - g0) / (z1 - z0);
      return z1;
    }
    if ((g1 > 0.0) != (g0 > 0.0)) {
      lo = z0 < z1 ? z0 : z1;
      hi = z0 < z1 ? z1 : z0;
      g_lo = z0 < z1 ? g0 : g1;
      g_hi = z0 < z1 ? g1 : g0;
      bracketed = true;
      break;
    }
    const double secant = (g1 - g0) / (z1 - z0);
    z0 = z1;
    g0 = g1;
    step = secant < 0.0 ? -g1 / secant : 2.0 * step;
  }
  if (!bracketed) return z0;
  // Illinois regula falsi on [lo, hi], g(lo) > 0 > g(hi).
  int side = 0;
  double z = lo;
  while (evaluations < kMaxEvaluations) {
    z = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    const double g = balance(z);
    ++evaluations;
    if (settled(g)) break;
    if (g > 0.0) {
      lo = z;
      g_lo = g;
      if (side == 1) g_hi *= 0.5;
      side = 1;
    } else {
      hi = z;
      g_hi = g;
      if (side == -1) g_lo *= 0.5;
      side = -1;
    }
  }
  if (hi > lo && g_lo != g_hi) run->slope = (g_hi - g_lo) / (hi - lo);
  return z;
}

void ScrewStage::DoEvaluate(const PartState& part, StageState* state,
                            StageOutput* out) const noexcept {
  auto* run = static_cast<RunState*>(state);
  MatingPose device = MatingPoseOf(part);
  device.depth -= options_.depth_origin;
  const double dt = run->started ? part.time - run->time : 0.0;
  if (!run->started || out->stage != StageId::kConstrained) {
    // Handed over by the positioning stage: the part is where that stage left it.
    run->started = true;
    run->depth = out->stage == StageId::kConstrained ? device.depth : out->pose.depth;
    run->angle = device.angle;
    run->slope = 0.0;
    run->law = LawState{};
    run->screw = ScrewOutput{};
    run->screw.active = true;
  }
  run->time = part.time;
  out->contact_evaluations = 0;
  if (options_.turn.speed > 0.0) {
    if (!run->screw.stopped) run->angle += options_.turn.speed * dt;
  } else {
    run->angle = device.angle;
  }
  run->depth = SettleDepth(run->angle, device.depth, run, out);

  MatingPose pose;
  pose.depth = run->depth;
  pose.angle = run->angle;
  analyzer_.Evaluate(pose, &out->contact);
  ++out->contact_evaluations;
  MatingMotion motion;
  motion.depth = pose.depth;
  motion.angle = pose.angle;
  motion.velocity = part.velocity;
  motion.angular_velocity = part.angular_velocity;
  if (!out->contact.engaged) run->law = LawState{};
  // The flanks' share alone: the same contact without the face, from the same junctions.
  LawState before = run->law;
  ContactState flanks = out->contact;
  flanks.stop_closure = 0.0;
  Wrench thread;
  law_.Evaluate(flanks, motion, &before, &thread);
  law_.Evaluate(out->contact, motion, &run->law, &out->wrench);
  out->elastic = law_.CheckElasticLimit(out->contact);

  ScrewOutput& screw = run->screw;
  screw.torque = -out->wrench.torque.y();
  screw.thread_torque = -thread.torque.y();
  screw.head_torque = screw.torque - screw.thread_torque;
  screw.preload = thread.force.y() - out->wrench.force.y();
  if (!screw.seated && out->contact.stop_closure > 0.0) {
    screw.seated = true;
    screw.snug_angle = run->angle;
  }
  const ScrewTurn& turn = options_.turn;
  switch (turn.target) {
    case TurnTarget::kNone:
      break;
    case TurnTarget::kTorque:
      screw.stopped = screw.stopped || screw.torque >= turn.value;
      break;
    case TurnTarget::kAngle:
      screw.stopped = screw.stopped || (screw.seated && run->angle - screw.snug_angle >= turn.value);
      break;
    case TurnTarget::kPreload:
      screw.stopped = screw.stopped || screw.preload >= turn.value;
      break;
  }
  out->screw = screw;
  out->pose = pose;
  if (options_.moving == Role::kOuter) {
    // The reflection in z of the analyzer's frame (AnalyzerPose); the axis and the twist stay.
    const Eigen::Vector3d reflect(1.0, 1.0, -1.0);
    out->wrench.force = out->wrench.force.cwiseProduct(reflect);
    out->wrench.torque = out->wrench.torque.cwiseProduct(reflect);
    SceneContact(&out->contact, options_.moving);
  }
  out->stiffness = 0.0;
  out->gap = std::numeric_limits<double>::infinity();
  out->gap_direction.setZero();
  out->next = run->depth < 0.0 && !out->contact.engaged ? StageId::kPositioning
                                                        : StageId::kConstrained;
}

}  // namespace fitfeel
