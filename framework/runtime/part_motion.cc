#include "framework/runtime/part_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "framework/core/error.h"
#include "framework/core/number_text.h"

namespace fitfeel {

PartMotion::PartMotion(const PartMotionSettings& settings, double period)
    : settings_(settings), period_(period) {
  if (!(std::isfinite(period) && period > 0.0 && period <= 1.0)) {
    throw UserError("part motion: the period must be in (0, 1] s, not " + MessageNumber(period));
  }
  if (!(std::isfinite(settings.damping) && settings.damping >= 0.0 &&
        settings.damping <= kMaxPartDamping)) {
    throw UserError("part motion: damping must be in [0, 1e6] N*s/m, not " +
                    MessageNumber(settings.damping));
  }
}

double PartMotion::ExplicitStabilityBound(double mass) const {
  // A part held rigidly on the axis (no mass) cannot be destabilised by a contact stiffness.
  const double m = mass, h = period_, c = settings_.damping;
  return m > 0.0 ? (4.0 + 2.0 * h * c / m) * m / (h * h) : std::numeric_limits<double>::infinity();
}

void PartMotion::Place(const DeviceState& device, const PartMotionState& state,
                       PartState* part) const noexcept {
  part->time = device.time;
  part->position = device.position;
  part->orientation = device.orientation;
  part->velocity = device.velocity;
  part->angular_velocity = device.angular_velocity;
  part->settle_load = settings_.radial == RadialMotion::kQuasiStatic ? LoadAt(device)
                                                                     : Eigen::Vector2d(0.0, 0.0);
  part->free_rotation = settings_.rotation == RotationMotion::kFree;
  part->applied_torque = part->free_rotation ? TorqueAt(settings_.torque, device.time) : 0.0;
  if (settings_.radial == RadialMotion::kDynamic && state.floating) {
    part->position.x() = state.position.x();
    part->position.z() = state.position.y();
    part->velocity.x() = state.velocity.x();
    part->velocity.z() = state.velocity.y();
  }
}

void PartMotion::Step(const DeviceState& device, const Wrench& wrench,
                      const ContactFeedback& feedback, PartMotionState* state) const noexcept {
  if (settings_.radial != RadialMotion::kDynamic) return;
  const double m = MassAt(device);
  PartMotionState& s = *state;
  if (!(m > 0.0)) {
    // Held by the device (the robot carries the weight before the entrance).
    s.floating = false;
    return;
  }
  if (!s.floating) {
    // The part floats from where the device held it.
    s.position = Eigen::Vector2d(device.position.x(), device.position.z());
    s.velocity = Eigen::Vector2d(device.velocity.x(), device.velocity.z());
    s.floating = true;
  }
  const double h = period_;
  const double c = settings_.damping;
  const Eigen::Vector2d load = LoadAt(device);
  const Eigen::Vector2d contact(wrench.force.x(), wrench.force.z());
  const Eigen::Vector2d x = s.position;
  Eigen::Vector2d v = s.velocity;
  const double stiffness = SanitizedStiffness(feedback.stiffness);
  const double gap = feedback.gap >= 0.0 ? feedback.gap : 0.0;
  // At a kink of the piecewise-linear contact force (an assembly-space vertex, a row entering)
  // the stage's 1 nm probe can read a fraction of the stiffness for a tick. Too soft a slope
  // makes the step overshoot (a Newton step on a kink), too stiff a one only slows the approach,
  // so the step takes the larger of the probe and 0.9 of the previous tick's slope: a dip of one
  // tick is bridged, a real softening is followed within ~20 ticks.
  Eigen::Vector2d anchor_velocity(0.0, 0.0);
  const double k = stiffness > 0.0 ? std::max(stiffness, 0.9 * s.previous_stiffness) : 0.0;
  s.previous_stiffness = k > 0.0 ? k : 0.9 * s.previous_stiffness;
  if (k > 0.0) {
    // The anchor from the probed slope (the law's own), not the bridged one used to step.
    const Eigen::Vector2d anchor = x + contact / stiffness;
    const Eigen::Vector2d travel =
        s.has_anchor ? Eigen::Vector2d(anchor - s.previous_anchor) : Eigen::Vector2d(0.0, 0.0);
    s.previous_anchor = anchor;
    s.has_anchor = true;
    v = (m * v + h * (contact + load + k * travel)) / (m + h * c + h * h * k);
    anchor_velocity = travel / h;
    // The contact as a plane for the next tick (through the anchor expected then, normal along
    // the force), in case the next pose lands just outside it.
    const double magnitude = contact.norm();
    s.plane_valid = magnitude > 0.0;
    if (s.plane_valid) {
      s.plane_normal = contact / magnitude;
      s.plane_point = anchor + travel;
      s.plane_stiffness = k;
    }
  } else {
    s.has_anchor = false;
    v = (m * v + h * (contact + load)) / (m + h * c);
    // A tick without contact right after one with contact is usually the part resting a hair
    // outside the surface it was pushed back to. A free step from there would fall g h^2
    // (9.8 um at 1 kHz, more than most fits' clearance) deep into that surface within one tick;
    // if it would cross the remembered plane, the step meets it as the contact step above
    // would, along its normal (tangentially the part stays free). Only for one tick: a part that
    // is still free next tick has really left the contact.
    const Eigen::Vector2d free = x + h * v;
    const Eigen::Vector2d& direction = feedback.gap_direction;
    if (std::isfinite(gap) && s.previous_stiffness > 0.0 && direction.norm() > 0.5) {
      // The surface at the end of the free way, as a plane facing the part.
      s.plane_point = x + gap * direction;
      s.plane_normal = -direction;
      s.plane_stiffness = s.previous_stiffness;
      s.plane_valid = true;
    }
    if (s.plane_valid && (free - s.plane_point).dot(s.plane_normal) < 0.0) {
      const Eigen::Vector2d& n = s.plane_normal;
      const double kp = s.plane_stiffness;
      const Eigen::Vector2d v0 = s.velocity;
      const double vn =
          (m * v0.dot(n) + h * ((contact + load).dot(n) + kp * (s.plane_point - x).dot(n))) /
          (m + h * c + h * h * kp);
      v += (vn - v.dot(n)) * n;
    }
    s.plane_valid = false;
  }
  s.position += h * v;
  // v is the step's mean velocity. Its end velocity differs in contact: a contact far stiffer
  // than the tick resolves (h^2 k >> m) has settled within the step, so the part ends moving with
  // the contact's anchor, not with the velocity that carried it there (which, kept, would fling
  // it micrometres per tick into free flight). That makes such a contact inelastic at the tick's
  // scale; a soft one (h^2 k << m) keeps v.
  Eigen::Vector2d end = v;
  if (k > 0.0) {
    const double settled = h * h * k / (m + h * h * k);
    end = (1.0 - settled) * v + settled * anchor_velocity;
  }
  s.velocity = end;
}

}  // namespace fitfeel
