#include "framework/runtime/screw_stage.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "framework/core/demand.h"
#include "framework/core/error.h"
#include "framework/runtime/part_state.h"

namespace fitfeel {

struct ScrewStage::RunState final : StageState {
  bool started = false;
  Eigen::Vector2d tilt{0.0, 0.0};  // this tick's, in the analyzer's frame
  double time = 0.0;
  double depth = 0.0, angle = 0.0;
  // d(axial force)/d(depth) where the last settle ended (N/m, < 0), for the next tick's first step.
  double slope = 0.0;
  LawState law;
  ScrewOutput screw;
  // The device's twist unwrapped across turns (MatingPoseOf gives it within half a turn), and
  // the part's resisting torque with its rise per radian, for a hand's torsional coupling.
  double device_raw = 0.0, device_twist = 0.0;
  double resisting = 0.0, resisting_slope = 0.0;
  // The advance per radian of turn over the last tick, m/rad (the lead's c while the part runs
  // on a flank).
  double advance = 0.0;
};

ScrewStage::ScrewStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law,
                       const Options& options)
    : analyzer_(analyzer), law_(law), options_(options) {
  if (!analyzer.prepared()) throw UserError("screw stage needs a prepared contact analyzer");
  if (!std::isfinite(options.depth_origin) || !(options.proxy_stiffness > 0.0) ||
      !std::isfinite(options.axial_load) || !(options.turn.speed >= 0.0) ||
      !(options.lead > 0.0 && std::isfinite(options.lead)) || !(options.twist_stiffness > 0.0)) {
    throw UserError(
        "screw stage: the depth origin, axial load and turning speed must be finite, "
        "the lead and the proxy stiffness > 0");
  }
}

std::unique_ptr<StageState> ScrewStage::DoMakeState() const { return std::make_unique<RunState>(); }

double ScrewStage::AxialForce(double depth, double angle, const Eigen::Vector2d& tilt,
                              const LawState& law, StageOutput* out) const noexcept {
  MatingPose pose;
  pose.depth = depth;
  pose.angle = angle;
  pose.tilt = tilt;
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

double ScrewStage::SettleDepth(double previous_angle, double device_depth, RunState* run,
                               StageOutput* out) const noexcept {
  const double k = options_.proxy_stiffness;
  const bool hand = std::isfinite(k);
  const double angle = run->angle;
  // The balance g(z) = contact + load falls with z: the contact pushes back harder the further
  // the part advances, and so does the hand's spring.
  auto balance = [&](double z) {
    const double load = hand ? k * (device_depth - z) : options_.axial_load;
    return AxialForce(z, angle, run->tilt, run->law, out) + load;
  };
  // The part advances with its turn as it did the last tick (along the lead while it runs on a
  // flank, less once the face holds it): from there the contact is nearly the last tick's, and
  // one step on the last slope usually lands.
  double z = run->depth + run->advance * (angle - previous_angle);
  double g = balance(z);
  int evaluations = 1;
  // Settled within a thousandth of a newton, or a bracket narrower than 0.1 nm (0.1 N at the
  // stiffness of a tightened joint): below what any device renders.
  constexpr double kForce = 1e-3, kWidth = 1e-10;
  double lo = -std::numeric_limits<double>::infinity(), hi = -lo, g_lo = 0.0, g_hi = 0.0;
  auto bracket = [&](double at, double value) {
    if (value > 0.0 && at > lo) {
      lo = at;
      g_lo = value;
    } else if (value < 0.0 && at < hi) {
      hi = at;
      g_hi = value;
    }
  };
  bracket(z, g);
  double slope = run->slope < 0.0 ? run->slope : (hand ? -k : 0.0);
  double step = 1e-6;
  // A tick moves the part an eighth of a pitch at most beyond the lead: no load makes a nut jump
  // its flanks, and a settle that has not met them stops short of the next turn's.
  const double reach = options_.lead / 8.0, least = z - reach, most = z + reach;
  int side = 0;  // Illinois: the bracket end that moved last
  while (std::abs(g) > kForce && evaluations < kMaxEvaluations && !(hi - lo <= kWidth)) {
    double next = 0.0;
    const bool closed = std::isfinite(lo) && std::isfinite(hi);
    if (closed) {
      // Regula falsi, the end that stays twice in a row halved (Illinois).
      next = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    } else if (slope < 0.0) {
      next = z - g / slope;
    } else {
      // Flat: the part crosses its flanks' play. Doubling steps until it meets a flank.
      next = z + std::copysign(step, g);
      step *= 2.0;
    }
    next = std::clamp(next, least, most);
    if (next == z) break;  // at the tick's reach, the flanks not met
    const double g_next = balance(next);
    ++evaluations;
    if (g_next != g && next != z) {
      const double secant = (g_next - g) / (next - z);
      slope = secant < 0.0 ? secant : 0.0;
    }
    if (closed) {
      if (g_next > 0.0) {
        if (side == 1) g_hi *= 0.5;
        side = 1;
      } else {
        if (side == -1) g_lo *= 0.5;
        side = -1;
      }
    }
    bracket(next, g_next);
    z = next;
    g = g_next;
  }
  if (slope < 0.0) run->slope = slope;
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
    run->device_raw = run->device_twist = device.angle;
    run->resisting = run->resisting_slope = 0.0;
    run->advance = options_.lead / (2.0 * std::numbers::pi);
  }
  run->time = part.time;
  out->contact_evaluations = 0;
  const double previous_angle = run->angle;
  double twist_step = device.angle - run->device_raw;
  twist_step -= 2.0 * std::numbers::pi * std::round(twist_step / (2.0 * std::numbers::pi));
  run->device_raw = device.angle;
  run->device_twist += twist_step;
  const double k_twist = options_.twist_stiffness;
  if (options_.turn.speed > 0.0) {
    if (!run->screw.stopped) run->angle += options_.turn.speed * dt;
  } else if (!std::isfinite(k_twist)) {
    run->angle = run->device_twist;
  } else {
    // One Newton step a tick on the spring's pull against the contact's resisting torque, on the
    // torque's last rise per radian: the part turns as far as the hand's twist can make it.
    // An eighth of a turn a tick at most, as the advance: no hand spins a nut faster.
    const double step = (k_twist * (run->device_twist - run->angle) - run->resisting) /
                        (k_twist + run->resisting_slope);
    run->angle += std::clamp(step, -0.25 * std::numbers::pi, 0.25 * std::numbers::pi);
  }
  // The tilt as the analyzer takes it (AnalyzerPose): reflected in z where the outer part moves.
  run->tilt = device.tilt + options_.tilt;
  if (options_.moving == Role::kOuter) run->tilt.y() = -run->tilt.y();
  const double angle = run->angle;
  const double previous_depth = run->depth;
  run->depth = SettleDepth(previous_angle, device.depth, run, out);
  if (angle != previous_angle) {
    // Bounded by the lead: a tick that jumped its flanks' play says nothing of the next.
    run->advance = std::clamp((run->depth - previous_depth) / (angle - previous_angle), 0.0,
                              options_.lead / (2.0 * std::numbers::pi));
  }

  // The settle's last evaluation was at this pose: its contact stands.
  MatingPose pose;
  pose.depth = run->depth;
  pose.angle = run->angle;
  pose.tilt = run->tilt;
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
  if (run->angle != previous_angle) {
    run->resisting_slope =
        std::max(0.0, (screw.torque - run->resisting) / (run->angle - previous_angle));
  }
  run->resisting = screw.torque;
  screw.thread_torque = -thread.torque.y();
  screw.head_torque = screw.torque - screw.thread_torque;
  screw.preload = thread.force.y() - out->wrench.force.y();
  // A hand feels its torsional spring, which at rest pulls as hard as the contact resists.
  if (options_.turn.speed == 0.0 && std::isfinite(k_twist)) {
    out->wrench.torque.y() = -k_twist * (run->device_twist - run->angle);
  }
  // And along the axis its coupling spring (the god object's): bounded by the spring's reach,
  // equal to the contact's force where the part settled, and stiff as the spring to the device
  // while the flanks or the face hold the part.
  const double k = options_.proxy_stiffness;
  const bool hand = std::isfinite(k);
  if (hand) out->wrench.force.y() = k * (run->depth - device.depth);
  out->stiffness = hand && out->contact.interference ? k : 0.0;
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
      screw.stopped =
          screw.stopped || (screw.seated && run->angle - screw.snug_angle >= turn.value);
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
  out->gap = std::numeric_limits<double>::infinity();
  out->gap_direction.setZero();
  out->next =
      run->depth < 0.0 && !out->contact.engaged ? StageId::kPositioning : StageId::kConstrained;
}

}  // namespace fitfeel
