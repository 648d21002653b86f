#include "devices/simulated/simulated_device.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"

namespace fitfeel::simulated {
namespace {

void Require(bool ok, const std::string& what) {
  if (!ok) throw UserError("simulated device: " + what);
}

bool InRange(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

}  // namespace

void Validate(const Settings& s) {
  Require(s.tilt.allFinite() && s.tilt.norm() <= kMaxTilt, "tilt must be within 1 deg");
  Require(s.tilt_stiffness > 0.0, "the hand's tilt_stiffness must be positive");
  Require(std::isinf(s.tilt_stiffness) || s.mode == Settings::Mode::kScripted,
          "only a hand holds the part compliantly (tilt_stiffness)");
  Require(s.mode != Settings::Mode::kConstantRotation || s.tilt.isZero(),
          "a rotary drive holds the part aligned (no tilt)");
  if (s.mode == Settings::Mode::kConstantSpeed) {
    Require(InRange(s.speed, 0.0, 1.0) && s.speed > 0.0, "speed must be in (0, 1] m/s");
    Require(InRange(s.start_offset, 0.0, 1.0), "start_offset must be in [0, 1] m");
    Require(InRange(s.stop_force, 0.0, 1e6), "stop_force must be in [0, 1] MN");
    return;
  }
  if (s.mode == Settings::Mode::kConstantRotation) {
    // 100 rad/s (~950 rpm) is far beyond any plain bearing's oscillation; a swing of more than
    // half a turn each way is a rotation.
    Require(InRange(s.angular_speed, 0.0, 100.0) && s.angular_speed > 0.0,
            "angular_speed must be in (0, 100] rad/s");
    Require(InRange(s.swing, 0.0, M_PI + 1e-9),
            "swing must be in [0, 180] deg (0: continuous rotation)");
    return;
  }
  Require(!s.waypoints.empty(), "a scripted run needs at least one waypoint");
  for (std::size_t i = 0; i < s.waypoints.size(); ++i) {
    const auto& w = s.waypoints[i];
    Require(InRange(w.time, 0.0, 1e5), "waypoint times must be in [0, 1e5] s");
    Require(w.position.allFinite() && w.position.cwiseAbs().maxCoeff() <= 10.0,
            "waypoint positions must be within 10 m of the entrance");
    Require(i == 0 || w.time > s.waypoints[i - 1].time, "waypoint times must increase strictly");
    Require(InRange(w.angle, -kMaxWaypointAngle, kMaxWaypointAngle),
            "waypoint angles must be within 20 turns");
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

DeviceSpec SimulatedDevice::DoSpec() const {
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
  } else {
    spec.model = "simulated robot (constant speed, constant radial load)";
  }
  // A position-controlled axis renders any stiffness: what moves under the force is the part
  // (PartMotion), which takes the contact's stiffness implicitly.
  spec.max_stiffness = std::numeric_limits<double>::infinity();
  if (settings_.mode == Settings::Mode::kScripted) {
    // The hand stands for a person at a haptic device, which renders a sampled spring passively
    // only below K = 2 b / T with b the damping holding it (Colgate & Schenkel 1997): the
    // stiffest wall this hand meets. The runtime then couples the part to the hand by a spring
    // no stiffer (a god object), as it does for a real device.
    spec.max_stiffness = 2.0 * settings_.hand_damping / period_;
  }
  spec.workspace = Eigen::Vector3d::Constant(20.0);
  spec.force_mapping = settings_.force_mapping;
  if (!settings_.device_model.empty()) {
    // The trajectory stays this device's; what it renders is the named device's.
    DeviceSpec named = LookupDeviceSpec(settings_.device_model);
    named.model = spec.model + " as " + named.model;
    named.native_rate = spec.native_rate;
    named.force_mapping = settings_.force_mapping;
    return named;
  }
  return spec;
}

void SimulatedDevice::DoStart(double period) {
  Validate(settings_);
  period_ = period;
  time_ = 0.0;
  // The twist about y comes after the swing in DoRead, so that MatingPoseOf's swing-twist
  // decomposition reads both back.
  const double tilt = settings_.tilt.norm();
  swing_ = tilt > 0.0
               ? Eigen::Quaterniond(Eigen::AngleAxisd(
                     tilt, Eigen::Vector3d(settings_.tilt.x(), 0.0, settings_.tilt.y()) / tilt))
               : Eigen::Quaterniond::Identity();
  delivered_.SetZero();
  velocity_.setZero();
  stiffness_ = 0.0;
  stopped_ = false;
  stop_position_ = 0.0;
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

void SimulatedDevice::WristTwist(double time, double* angle, double* rate) const noexcept {
  const auto& w = settings_.waypoints;
  *rate = 0.0;
  *angle = w.back().angle;
  if (time <= w.front().time) {
    *angle = w.front().angle;
    return;
  }
  for (std::size_t i = 1; i < w.size(); ++i) {
    if (time < w[i].time) {
      *rate = (w[i].angle - w[i - 1].angle) / (w[i].time - w[i - 1].time);
      *angle = w[i - 1].angle + (time - w[i - 1].time) * *rate;
      return;
    }
  }
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

double SimulatedDevice::DoReach(double duration) const {
  // The robot's leading end moves by the clock alone (a force-driven press stops it sooner); the
  // rotary drive and the hand are not bounded here.
  if (settings_.mode != Settings::Mode::kConstantSpeed || !(duration >= 0.0)) {
    return std::numeric_limits<double>::infinity();
  }
  return -settings_.start_offset + settings_.speed * duration;
}

double SimulatedDevice::DoAngularReach(double duration) const {
  // The rotary drive turns by the clock alone: its swing's amplitude, or its whole travel.
  if (settings_.mode != Settings::Mode::kConstantRotation || !(duration >= 0.0)) {
    return std::numeric_limits<double>::infinity();
  }
  return settings_.swing > 0.0 ? settings_.swing : settings_.angular_speed * duration;
}

std::optional<Eigen::Vector2d> SimulatedDevice::DoHeldTilt() const {
  if (settings_.tilt.isZero()) return std::nullopt;
  return settings_.tilt;
}

void SimulatedDevice::DoRead(double time, DeviceState* out) noexcept {
  time_ = time;
  out->orientation = swing_;
  out->angular_velocity.setZero();
  if (settings_.mode == Settings::Mode::kConstantSpeed) {
    // Computed from the time, never accumulated: the axial position is exact at every tick.
    position_.y() = stopped_ ? stop_position_ : -settings_.start_offset + settings_.speed * time;
    velocity_.y() = stopped_ ? 0.0 : settings_.speed;
  } else {
    double angle = 0.0, rate = 0.0;
    if (settings_.mode == Settings::Mode::kConstantRotation) {
      Twist(time, &angle, &rate);
    } else {
      WristTwist(time, &angle, &rate);
    }
    // Reduced to (-pi, pi] before the half angle: the quaternion stays in one hemisphere and the
    // twist MatingPoseOf reads back is the angle itself, to rounding.
    angle = std::remainder(angle, 2.0 * M_PI);
    out->orientation =
        swing_ * Eigen::Quaterniond(std::cos(0.5 * angle), 0.0, std::sin(0.5 * angle), 0.0);
    out->angular_velocity.y() = rate;
  }
  out->time = time;
  out->position = position_;
  out->velocity = velocity_;
  out->buttons = 0;
  out->delivered = delivered_;
}

void SimulatedDevice::DoWrite(const Wrench& wrench) noexcept {
  delivered_ = wrench;
  const double h = period_;
  if (settings_.mode == Settings::Mode::kConstantSpeed && settings_.stop_force > 0.0 && !stopped_ &&
      -wrench.force.y() >= settings_.stop_force) {
    // The press's force monitor: the ram holds where the resistance reached the set force.
    stopped_ = true;
    stop_position_ = position_.y();
  }
  // The robot and the drive are position-controlled: the force moves nothing of theirs.
  if (settings_.mode != Settings::Mode::kScripted) return;
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
