#pragma once

#include <numbers>
#include <vector>

#include <Eigen/Core>

#include "framework/device/device.h"

namespace fitfeel::simulated {

// The largest waypoint angle, rad: twenty turns, a nut run down by the fingers.
inline constexpr double kMaxWaypointAngle = 40.0 * std::numbers::pi;

struct Waypoint {
  double time = 0.0;                        // s since the start of the run
  Eigen::Vector3d position{0.0, 0.0, 0.0};  // leading end, scene frame, m
  // The wrist's turn about the mating axis y, rad: the device's orientation (the part's twist, a
  // position the hand holds; it has no dynamics of its own).
  double angle = 0.0;
};

struct Settings {
  enum class Mode { kConstantSpeed, kConstantRotation, kScripted };
  Mode mode = Mode::kConstantSpeed;

  // kConstantSpeed: the paper's case-study robot.
  double speed = 10e-3;        // insertion speed along +y, m/s (paper: 10 mm/s)
  double start_offset = 1e-3;  // leading end this far before the entrance at t = 0, m
  // A force-driven press: the ram stops advancing (and holds its position) at the first tick whose
  // axial resistance reaches this force; 0: it never stops (a position-driven robot).
  double stop_force = 0.0;  // N

  // kConstantRotation: a drive turning the moving part about the mating axis y at a constant
  // angular speed, its leading end held at the entrance (depth 0: a captive part such as a
  // bearing's ball, whose analyzer ignores the depth).
  double angular_speed = 0.0;  // rad/s, > 0
  // Half angle beta of an oscillation (ISO 12240 / maker catalogues: one full oscillation sweeps
  // 4 beta): 0 for continuous rotation, else the angle runs 0 -> +beta -> -beta -> +beta ... at
  // angular_speed (a triangle wave: constant speed, reversing at the ends).
  double swing = 0.0;  // rad, [0, pi]

  // kScripted: a hand (mass, spring-damper) pulled along straight segments between waypoints.
  std::vector<Waypoint> waypoints;  // times strictly increasing
  double hand_mass = 0.0;           // kg
  double hand_stiffness = 0.0;      // N/m
  double hand_damping = 0.0;        // N*s/m
  // Any mode: a known haptic device's model (framework/device/device_specs.h) whose limits the
  // run renders with (its spec's forces, stiffness budget, damping and workspace); empty: none.
  std::string device_model;
  // How the run maps the scene's force onto the device's (`force_mapping`), handed over in the
  // spec.
  ForceMappingKind force_mapping = ForceMappingKind::kLinear;
  // Physiological tremor added to the target across the mating axis: a circle of `tremor_amplitude`
  // in (x, z) at `tremor_frequency` (x = A sin(2 pi f t), z = A cos(2 pi f t) - A, so it starts at
  // the waypoint). 0: none. Defaults of the key: 0.1 mm at 10 Hz (docs in README.md).
  double tremor_amplitude = 0.0;  // m
  double tremor_frequency = 0.0;  // Hz
  // A constant aiming error added to every waypoint across the axis: where a person's hand puts
  // the part's axis when aiming at the bore, (x, z).
  Eigen::Vector2d aim_error{0.0, 0.0};  // m
  // kConstantSpeed and kScripted: the tilt the part is held at for the whole run, the (x, z)
  // components of the rotation vector that turns +y onto the part's axis (MatingPose::tilt),
  // rad, at most kMaxTilt: a robot's crooked hold, or a hand that starts the part crooked and
  // keeps it so (the hand's wrist is stiff in tilt: it does not turn the part into line).
  Eigen::Vector2d tilt{0.0, 0.0};
  // kScripted with a tilt: how stiffly the fingers and wrist keep it, N*m/rad (Device::
  // held_tilt_stiffness); infinite: held rigidly, as the robot does.
  double tilt_stiffness = std::numeric_limits<double>::infinity();
};

// The largest held tilt: the positioning stage hands a part to the constrained stage only within
// its alignment tolerance (1 degree, positioning_stage.h).
inline constexpr double kMaxTilt = 0.017453292519943295;

// The simulated device of the paper's case study and a scripted hand (plugin
// fitfeel.device.simulated). The frame is the run's (positioning_stage.h): y the mating axis, the
// fixed part's entrance at y = 0, gravity along -z.
//
// Constant speed: the robot drives the leading end along +y at `speed`, exactly: y(t) =
// -start_offset + speed * t, whatever force is rendered (a position-controlled robot axis).
//
// Constant rotation: the drive turns the part about y at `angular_speed`, continuously or
// oscillating by +-`swing`, whatever torque is rendered (a position-controlled rotary axis), with
// the leading end at the entrance (y = 0) from the first tick: the orientation's twist about y is
// the mating pose's angle and angular_velocity.y its rate. Radially it is the robot below.
//
// Radially both are a trajectory: the device holds the leading end on the axis (x = z = 0). The
// load that acts on the part once it is inside (its weight, as the paper's robot positions the
// shaft before inserting it and then lets its weight act) and whether the part is then held,
// settled quasi-statically or floats under it are the scene's `part_motion` (PartMotion), not the
// device's.
//
// Scripted: the leading end is a hand of mass m_h held by a spring k_h and damper b_h to a target
// moving in straight lines between waypoints (held at the first before it and at the last after
// it), plus the rendered force. The hand's own spring-damper is integrated implicitly (backward
// Euler, unconditionally stable) and the rendered force explicitly.
class SimulatedDevice final : public Device {
 public:
  SimulatedDevice();
  // Throws UserError for settings out of range.
  void Configure(const Settings& settings);
  using Device::Configure;
  const Settings& settings() const { return settings_; }

  DeviceSpec DoSpec() const override;
  std::optional<Eigen::Vector2d> DoHeldTilt() const override;
  double DoHeldTiltStiffness() const override { return settings_.tilt_stiffness; }
  double DoReach(double duration) const override;
  double DoAngularReach(double duration) const override;

 protected:
  void DoConfigure(const ConfigNode& node) override;  // simulated_config.cc
  void DoStart(double period) override;
  void DoRead(double time, DeviceState* out) noexcept override;
  void DoWrite(const Wrench& wrench) noexcept override;
  void DoSetEnvironmentStiffness(double stiffness) noexcept override { stiffness_ = stiffness; }

 private:
  void Target(double time, Eigen::Vector3d* position, Eigen::Vector3d* velocity) const noexcept;
  // The aiming error and the tremor, added to the waypoints' target.
  void AddHandErrors(double time, Eigen::Vector3d* position,
                     Eigen::Vector3d* velocity) const noexcept;
  // kScripted: the wrist's twist about y and its rate at `time`, linear between the waypoints'
  // angles.
  void WristTwist(double time, double* angle, double* rate) const noexcept;
  // kConstantRotation: the twist about y and its rate at `time`, from the time alone (exact).
  void Twist(double time, double* angle, double* rate) const noexcept;

  Settings settings_;
  double period_ = 1e-3;
  double time_ = 0.0;  // of the last Read
  Eigen::Vector3d position_{0.0, 0.0, 0.0};
  Eigen::Vector3d velocity_{0.0, 0.0, 0.0};
  // The held tilt as a swing about an axis across y (Settings::tilt), made once at Start.
  Eigen::Quaterniond swing_ = Eigen::Quaterniond::Identity();
  Wrench delivered_;
  double stiffness_ = 0.0;      // of the contact behind the next wrench (scripted hand), N/m
  bool stopped_ = false;        // constant speed with stop_force: the ram has stopped
  double stop_position_ = 0.0;  // where, m
};

// Throws UserError naming the first setting out of range.
void Validate(const Settings& settings);

}  // namespace fitfeel::simulated
