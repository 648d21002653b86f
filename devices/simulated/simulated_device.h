#pragma once

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "framework/device/device.h"

namespace fitfeel::simulated {

// Standard gravity (CGPM 1901), m/s^2: turns the part's weight into its mass.
inline constexpr double kStandardGravity = 9.80665;

struct Waypoint {
  double time = 0.0;                        // s since the start of the run
  Eigen::Vector3d position{0.0, 0.0, 0.0};  // leading end, scene frame, m
};

struct Settings {
  enum class Mode { kConstantSpeed, kConstantRotation, kScripted };
  Mode mode = Mode::kConstantSpeed;

  // kConstantSpeed: the paper's case-study robot.
  double speed = 10e-3;         // insertion speed along +y, m/s (paper: 10 mm/s)
  double start_offset = 1e-3;   // leading end this far before the entrance at t = 0, m
  double radial_load = 0.0;     // constant radial load along -z (the part's weight), N
  double radial_damping = 0.0;  // viscous damping of the part's radial motion, N*s/m
  // A force-driven press: the ram stops advancing (and holds its position) at the first tick whose
  // axial resistance reaches this force; 0: it never stops (a position-driven robot).
  double stop_force = 0.0;  // N
  // How the radial load meets the contact: kQuasiStatic (default) has the constrained stage place
  // the part where the contact balances the load each tick (DeviceState::settle_load), as the
  // paper's case study describes it; kDynamic integrates the part's radial motion (below).
  enum class Radial { kQuasiStatic, kDynamic };
  Radial radial = Radial::kQuasiStatic;

  // kConstantRotation: a drive turning the moving part about the mating axis y at a constant
  // angular speed, its leading end held at the entrance (depth 0: a captive part such as a
  // bearing's ball, whose analyzer ignores the depth). radial_load, radial_damping and radial act
  // as in kConstantSpeed.
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
  // Physiological tremor added to the target across the mating axis: a circle of `tremor_amplitude`
  // in (x, z) at `tremor_frequency` (x = A sin(2 pi f t), z = A cos(2 pi f t) - A, so it starts at
  // the waypoint). 0: none. Defaults of the key: 0.1 mm at 10 Hz (docs in README.md).
  double tremor_amplitude = 0.0;   // m
  double tremor_frequency = 0.0;   // Hz
  // A constant aiming error added to every waypoint across the axis: where a person's hand puts
  // the part's axis when aiming at the bore, (x, z).
  Eigen::Vector2d aim_error{0.0, 0.0};  // m
};

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
// Radial, quasi-static (the default, `radial: quasi_static`): once the leading end is inside, the
// device asks the constrained stage to settle the part under its weight (DeviceState::settle_load)
// and integrates nothing across the axis. At 10 mm/s the shaft's radial contact modes (tens of kHz
// for a steel press fit) are far faster than anything the insertion excites, so the paper's
// statement of radial equilibrium ("a radial force upwards to balance the gravity") is the model.
//
// Radial, dynamic (`radial: dynamic`): across the axis the part floats: from the moment its leading
// end passes the entrance, its weight (radial_load, along -z) and the rendered radial force (x, z)
// act on the mass m = radial_load / g and move it. That mass is the part's own, which makes it the
// physical choice: in the case study the shaft settles onto the bore under its own weight ("the
// gravity of the shaft causes an offset of its axis vertically downward, which introduces a radial
// force upwards"), so the inertia that meets the radial contact force is the shaft's, not the
// robot's. Before the entrance the robot carries the weight and holds the part on the axis, as the
// paper's robot positions the shaft before inserting it. With no radial load there is no mass to
// move: the part stays on the axis.
//
// Integration is semi-implicit (symplectic) Euler with the damping, and the contact stiffness k
// the runtime hands over (Device::SetEnvironmentStiffness, 0 when free), taken implicitly:
//   v' = (m v + h (F + W)) / (m + h c + h^2 k),   x' = x + h v'.
// In free flight (k = 0) this is symplectic Euler, which keeps an oscillator's energy bounded
// where explicit Euler pumps it up and implicit Euler bleeds it away. In contact the force of the
// next position is linearised as F - k (x' - x): without that, a contact of stiffness k on the
// mass m sampled at period h is stable only while k < (4 + 2 h c / m) m / h^2 (0.82 N/um for a
// 2 N shaft at 1 kHz), and a steel press fit is about 3.7 N/nm: its natural frequency (~21 kHz)
// is far above the tick's, so the part must reach its equilibrium within a tick, which the
// linearised step does (for m << h^2 k it is a Newton step to F = -W). kExplicitStabilityBound
// gives the bound for a device that is not told the stiffness.
//
// The contact is not still: as the part advances, the position the contact holds it at (the
// energy-minimising axis under interference, the assembly space's edge in clearance) moves with
// depth, and a step that assumed it fixed would lag it by a tick, which a stiff contact turns into
// a large spurious force (K times the anchor's travel per tick, several N in the case study). With
// F = -K (x - a) the anchor is a = x + F / K, read off each tick; it is extrapolated linearly to
// the next tick (exact for an anchor moving at constant rate) and the step solves for
// F(x') = F - K (x' - x) + K (a' - a). Without contact history (first tick in contact) a' = a.
// A free tick right after a contact tick keeps that contact as a one-sided plane for the step
// (see DoWrite): a free fall of one tick is g h^2 = 9.8 um, deeper than most fits' clearance.
// When the runtime says how far the free way reaches (SetEnvironmentGap), the surface there is
// such a plane too, with the last contact stiffness.
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

  DeviceSpec spec() const override;
  // Radial (constant speed) or hand (scripted) mass, kg.
  double mass() const;
  // Largest contact stiffness an explicit contact force keeps stable on this mass at the period,
  // N/m: what applies when the runtime does not hand over the stiffness.
  double ExplicitStabilityBound() const;

 protected:
  void DoConfigure(const ConfigNode& node) override;  // simulated_config.cc
  void DoStart(double period) override;
  void DoRead(double time, DeviceState* out) noexcept override;
  void DoWrite(const Wrench& wrench) noexcept override;
  void DoSetEnvironmentStiffness(double stiffness) noexcept override { stiffness_ = stiffness; }
  void DoSetEnvironmentGap(double gap, const Eigen::Vector2d& direction) noexcept override {
    gap_ = gap;
    gap_direction_ = direction;
  }

 private:
  void Target(double time, Eigen::Vector3d* position, Eigen::Vector3d* velocity) const noexcept;
  // The aiming error and the tremor, added to the waypoints' target.
  void AddHandErrors(double time, Eigen::Vector3d* position,
                     Eigen::Vector3d* velocity) const noexcept;
  // kConstantRotation: the twist about y and its rate at `time`, from the time alone (exact).
  void Twist(double time, double* angle, double* rate) const noexcept;

  Settings settings_;
  double period_ = 1e-3;
  double time_ = 0.0;  // of the last Read
  Eigen::Vector3d position_{0.0, 0.0, 0.0};
  Eigen::Vector3d velocity_{0.0, 0.0, 0.0};
  Wrench delivered_;
  double stiffness_ = 0.0;  // of the contact behind the next wrench, N/m
  // Radial anchor of the contact at the previous tick (constant speed), valid while in contact.
  Eigen::Vector2d previous_anchor_{0.0, 0.0};
  bool has_anchor_ = false;
  // The contact of the previous tick as a plane (constant speed), valid for one free tick.
  Eigen::Vector2d plane_point_{0.0, 0.0};
  Eigen::Vector2d plane_normal_{0.0, 0.0};
  double plane_stiffness_ = 0.0;
  bool plane_valid_ = false;
  double previous_stiffness_ = 0.0;                       // slope used in the previous tick, N/m
  bool stopped_ = false;        // constant speed with stop_force: the ram has stopped
  double stop_position_ = 0.0;  // where, m
  double gap_ = std::numeric_limits<double>::infinity();  // free way along gap_direction_, m
  Eigen::Vector2d gap_direction_{0.0, 0.0};
};

// Throws UserError naming the first setting out of range.
void Validate(const Settings& settings);

}  // namespace fitfeel::simulated
