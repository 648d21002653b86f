#include "devices/simulated/simulated_device.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "framework/core/error.h"

namespace fitfeel::simulated {
namespace {

void Require(bool ok, const std::string& what) {
  if (!ok) throw UserError("simulated device: " + what);
}

bool InRange(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

}  // namespace

void Validate(const Settings& s) {
  if (s.mode == Settings::Mode::kConstantSpeed) {
    Require(InRange(s.speed, 0.0, 1.0) && s.speed > 0.0, "speed must be in (0, 1] m/s");
    Require(InRange(s.start_offset, 0.0, 1.0), "start_offset must be in [0, 1] m");
    Require(InRange(s.stop_force, 0.0, 1e6), "stop_force must be in [0, 1] MN");
    Require(InRange(s.radial_load, 0.0, 1e4), "radial_load must be in [0, 10] kN");
    Require(InRange(s.radial_damping, 0.0, 1e6), "radial_damping must be in [0, 1e6] N*s/m");
    return;
  }
  if (s.mode == Settings::Mode::kConstantRotation) {
    // 100 rad/s (~950 rpm) is far beyond any plain bearing's oscillation; a swing of more than
    // half a turn each way is a rotation.
    Require(InRange(s.angular_speed, 0.0, 100.0) && s.angular_speed > 0.0,
            "angular_speed must be in (0, 100] rad/s");
    Require(InRange(s.swing, 0.0, M_PI + 1e-9),
            "swing must be in [0, 180] deg (0: continuous rotation)");
    Require(InRange(s.radial_load, 0.0, 1e4), "radial_load must be in [0, 10] kN");
    Require(InRange(s.radial_damping, 0.0, 1e6), "radial_damping must be in [0, 1e6] N*s/m");
    return;
  }
  Require(!s.waypoints.empty(), "a scripted run needs at least one waypoint");
  for (std::size_t i = 0; i < s.waypoints.size(); ++i) {
    const auto& w = s.waypoints[i];
    Require(InRange(w.time, 0.0, 1e5), "waypoint times must be in [0, 1e5] s");
    Require(w.position.allFinite() && w.position.cwiseAbs().maxCoeff() <= 10.0,
            "waypoint positions must be within 10 m of the entrance");
    Require(i == 0 || w.time > s.waypoints[i - 1].time, "waypoint times must increase strictly");
  }
  Require(InRange(s.hand_mass, 0.0, 1e3) && s.hand_mass > 0.0, "hand mass must be in (0, 1000] kg");
  Require(InRange(s.hand_stiffness, 0.0, 1e8) && s.hand_stiffness > 0.0,
          "hand stiffness must be in (0, 1e8] N/m");
  Require(InRange(s.hand_damping, 0.0, 1e6), "hand damping must be in [0, 1e6] N*s/m");
}

SimulatedDevice::SimulatedDevice() = default;

void SimulatedDevice::Configure(const Settings& settings) {
  Validate(settings);
  settings_ = settings;
}

double SimulatedDevice::mass() const {
  return settings_.mode == Settings::Mode::kScripted ? settings_.hand_mass
                                                     : settings_.radial_load / kStandardGravity;
}

double SimulatedDevice::ExplicitStabilityBound() const {
  const double m = mass();
  const double c = settings_.mode == Settings::Mode::kScripted ? settings_.hand_damping
                                                               : settings_.radial_damping;
  // A part held rigidly on the axis (no mass) cannot be destabilised by a contact stiffness.
  return m > 0.0 ? (4.0 + 2.0 * period_ * c / m) * m / (period_ * period_)
                 : std::numeric_limits<double>::infinity();
}

DeviceSpec SimulatedDevice::spec() const {
  DeviceSpec spec;
  spec.native_rate = 1.0 / period_;
  // A simulated robot has no motor to saturate.
  spec.max_force = std::numeric_limits<double>::infinity();
  spec.max_continuous_force = spec.max_force;
  if (settings_.mode == Settings::Mode::kScripted) {
    spec.model = "simulated hand (scripted waypoints)";
    spec.damping = settings_.hand_damping;
  } else if (settings_.mode == Settings::Mode::kConstantRotation) {
    spec.model = "simulated rotary drive (constant angular speed, constant radial load)";
    spec.damping = settings_.radial_damping;
  } else {
    spec.model = "simulated robot (constant speed, constant radial load)";
    spec.damping = settings_.radial_damping;
  }
  // The contact is integrated implicitly with the stiffness the runtime hands over, so any
  // contact stiffness is stable; ExplicitStabilityBound() is the limit without it.
  spec.max_stiffness = std::numeric_limits<double>::infinity();
  if (settings_.mode == Settings::Mode::kScripted) {
    // The hand stands for a person at a haptic device, which renders a sampled spring passively
    // only below K = 2 b / T with b the damping holding it (Colgate & Schenkel 1997): the
    // stiffest wall this hand meets. The runtime then couples the part to the hand by a spring
    // no stiffer (a god object), as it does for a real device.
    spec.max_stiffness = 2.0 * settings_.hand_damping / period_;
  }
  spec.workspace = Eigen::Vector3d::Constant(20.0);
  return spec;
}

void SimulatedDevice::DoStart(double period) {
  Validate(settings_);
  period_ = period;
  time_ = 0.0;
  delivered_.SetZero();
  velocity_.setZero();
  stiffness_ = 0.0;
  has_anchor_ = false;
  plane_valid_ = false;
  previous_stiffness_ = 0.0;
  stopped_ = false;
  stop_position_ = 0.0;
  gap_ = std::numeric_limits<double>::infinity();
  gap_direction_.setZero();
  if (settings_.mode == Settings::Mode::kConstantSpeed) {
    position_ = Eigen::Vector3d(0.0, -settings_.start_offset, 0.0);
  } else if (settings_.mode == Settings::Mode::kConstantRotation) {
    position_.setZero();
  } else {
    Eigen::Vector3d v;
    Target(0.0, &position_, &v);
  }
}

void SimulatedDevice::Target(double time, Eigen::Vector3d* position,
                             Eigen::Vector3d* velocity) const noexcept {
  const auto& w = settings_.waypoints;
  velocity->setZero();
  if (time <= w.front().time) {
    *position = w.front().position;
    AddHandErrors(time, position, velocity);
    return;
  }
  for (std::size_t i = 1; i < w.size(); ++i) {
    if (time < w[i].time) {
      const double span = w[i].time - w[i - 1].time;
      *velocity = (w[i].position - w[i - 1].position) / span;
      *position = w[i - 1].position + (time - w[i - 1].time) * *velocity;
      AddHandErrors(time, position, velocity);
      return;
    }
  }
  *position = w.back().position;
  AddHandErrors(time, position, velocity);
}

void SimulatedDevice::AddHandErrors(double time, Eigen::Vector3d* position,
                                    Eigen::Vector3d* velocity) const noexcept {
  position->x() += settings_.aim_error.x();
  position->z() += settings_.aim_error.y();
  const double a = settings_.tremor_amplitude;
  if (!(a > 0.0)) return;
  const double omega = 2.0 * M_PI * settings_.tremor_frequency;
  position->x() += a * std::sin(omega * time);
  position->z() += a * (std::cos(omega * time) - 1.0);
  velocity->x() += a * omega * std::cos(omega * time);
  velocity->z() -= a * omega * std::sin(omega * time);
}

void SimulatedDevice::Twist(double time, double* angle, double* rate) const noexcept {
  const double omega = settings_.angular_speed;
  const double beta = settings_.swing;
  const double travel = omega * time;
  if (!(beta > 0.0)) {
    *angle = travel;
    *rate = omega;
    return;
  }
  // Triangle wave of amplitude beta: up from 0 to beta, down to -beta, up to 0, period 4 beta.
  const double phase = std::fmod(travel, 4.0 * beta);
  if (phase < beta) {
    *angle = phase;
    *rate = omega;
  } else if (phase < 3.0 * beta) {
    *angle = 2.0 * beta - phase;
    *rate = -omega;
  } else {
    *angle = phase - 4.0 * beta;
    *rate = omega;
  }
}

void SimulatedDevice::DoRead(double time, DeviceState* out) noexcept {
  time_ = time;
  out->orientation = Eigen::Quaterniond::Identity();
  out->angular_velocity.setZero();
  if (settings_.mode == Settings::Mode::kConstantSpeed) {
    // Computed from the time, never accumulated: the axial position is exact at every tick.
    position_.y() = stopped_ ? stop_position_ : -settings_.start_offset + settings_.speed * time;
    velocity_.y() = stopped_ ? 0.0 : settings_.speed;
  } else if (settings_.mode == Settings::Mode::kConstantRotation) {
    double angle = 0.0, rate = 0.0;
    Twist(time, &angle, &rate);
    // Reduced to (-pi, pi] before the half angle: the quaternion stays in one hemisphere and the
    // twist MatingPoseOf reads back is the angle itself, to rounding.
    angle = std::remainder(angle, 2.0 * M_PI);
    out->orientation = Eigen::Quaterniond(std::cos(0.5 * angle), 0.0, std::sin(0.5 * angle), 0.0);
    out->angular_velocity.y() = rate;
  }
  out->time = time;
  out->position = position_;
  out->velocity = velocity_;
  out->buttons = 0;
  out->delivered = delivered_;
  out->settle_load.setZero();
  if (settings_.mode != Settings::Mode::kScripted &&
      settings_.radial == Settings::Radial::kQuasiStatic && position_.y() >= 0.0) {
    out->settle_load = Eigen::Vector2d(0.0, -settings_.radial_load);
  }
}

void SimulatedDevice::DoWrite(const Wrench& wrench) noexcept {
  delivered_ = wrench;
  const double h = period_;
  if (settings_.mode == Settings::Mode::kConstantSpeed && settings_.stop_force > 0.0 &&
      !stopped_ && -wrench.force.y() >= settings_.stop_force) {
    // The press's force monitor: the ram holds where the resistance reached the set force.
    stopped_ = true;
    stop_position_ = position_.y();
  }
  if (settings_.mode != Settings::Mode::kScripted) {
    const double m = mass();
    // Held on the axis by the robot until the leading end is inside; with no weight, no mass;
    // settled by the stage in the quasi-static mode.
    if (m <= 0.0 || position_.y() < 0.0 || settings_.radial == Settings::Radial::kQuasiStatic) {
      return;
    }
    const double c = settings_.radial_damping;
    const Eigen::Vector2d load(0.0, -settings_.radial_load);
    const Eigen::Vector2d contact(wrench.force.x(), wrench.force.z());
    const Eigen::Vector2d x(position_.x(), position_.z());
    Eigen::Vector2d v(velocity_.x(), velocity_.z());
    // At a kink of the piecewise-linear contact force (an assembly-space vertex, a row entering)
    // the runtime's 1 nm probe can read a fraction of the stiffness for a tick. Too soft a slope
    // makes the step overshoot (a Newton step on a kink), too stiff a one only slows the
    // approach, so the step takes the larger of the probe and 0.9 of the previous tick's slope:
    // a dip of one tick is bridged, a real softening is followed within ~20 ticks.
    Eigen::Vector2d anchor_velocity(0.0, 0.0);
    const double k = stiffness_ > 0.0 ? std::max(stiffness_, 0.9 * previous_stiffness_) : 0.0;
    previous_stiffness_ = k > 0.0 ? k : 0.9 * previous_stiffness_;
    if (k > 0.0) {
      // The anchor from the probed slope (the law's own), not the bridged one used to step.
      const Eigen::Vector2d anchor = x + contact / stiffness_;
      const Eigen::Vector2d travel =
          has_anchor_ ? Eigen::Vector2d(anchor - previous_anchor_) : Eigen::Vector2d(0.0, 0.0);
      previous_anchor_ = anchor;
      has_anchor_ = true;
      v = (m * v + h * (contact + load + k * travel)) / (m + h * c + h * h * k);
      anchor_velocity = travel / h;
      // The contact as a plane for the next tick (through the anchor expected then, normal along
      // the force), in case the next pose lands just outside it.
      const double magnitude = contact.norm();
      plane_valid_ = magnitude > 0.0;
      if (plane_valid_) {
        plane_normal_ = contact / magnitude;
        plane_point_ = anchor + travel;
        plane_stiffness_ = k;
      }
    } else {
      has_anchor_ = false;
      v = (m * v + h * (contact + load)) / (m + h * c);
      // A tick without contact right after one with contact is usually the part resting a hair
      // outside the surface it was pushed back to. A free step from there would fall g h^2
      // (9.8 um at 1 kHz, more than most fits' clearance) deep into that surface within one
      // tick; if it would cross the remembered plane, the step meets it as the contact step
      // above would, along its normal (tangentially the part stays free). Only for one tick:
      // a part that is still free next tick has really left the contact.
      const Eigen::Vector2d free = x + h * v;
      if (std::isfinite(gap_) && previous_stiffness_ > 0.0 && gap_direction_.norm() > 0.5) {
        // The surface at the end of the free way, as a plane facing the part.
        plane_point_ = x + gap_ * gap_direction_;
        plane_normal_ = -gap_direction_;
        plane_stiffness_ = previous_stiffness_;
        plane_valid_ = true;
      }
      if (plane_valid_ && (free - plane_point_).dot(plane_normal_) < 0.0) {
        const Eigen::Vector2d& n = plane_normal_;
        const double kp = plane_stiffness_;
        const Eigen::Vector2d v0(velocity_.x(), velocity_.z());
        const double vn =
            (m * v0.dot(n) + h * ((contact + load).dot(n) + kp * (plane_point_ - x).dot(n))) /
            (m + h * c + h * h * kp);
        v += (vn - v.dot(n)) * n;
      }
      plane_valid_ = false;
    }
    position_.x() += h * v.x();
    position_.z() += h * v.y();
    // v is the step's mean velocity. Its end velocity differs in contact: a contact far stiffer
    // than the tick resolves (h^2 k >> m) has settled within the step, so the part ends moving
    // with the contact's anchor, not with the velocity that carried it there (which, kept, would
    // fling it micrometres per tick into free flight). That makes such a contact inelastic at the
    // tick's scale; a soft one (h^2 k << m) keeps v.
    Eigen::Vector2d end = v;
    if (k > 0.0) {
      const double settled = h * h * k / (m + h * h * k);
      end = (1.0 - settled) * v + settled * anchor_velocity;
    }
    velocity_.x() = end.x();
    velocity_.z() = end.y();
    return;
  }
  // Scripted hand: backward Euler for its spring-damper towards the target at the end of the
  // step and for the contact's stiffness, the rendered force at the current position.
  Eigen::Vector3d target, target_velocity;
  Target(time_ + h, &target, &target_velocity);
  const double m = settings_.hand_mass, k = settings_.hand_stiffness, b = settings_.hand_damping;
  velocity_ =
      (m * velocity_ + h * (k * (target - position_) + b * target_velocity + wrench.force)) /
      (m + h * b + h * h * (k + stiffness_));
  position_ += h * velocity_;
}

}  // namespace fitfeel::simulated
