#pragma once

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/device/device.h"

namespace fitfeel {

struct CouplingGains {
  double stiffness = 0.0;  // K_c, N/m
  double damping = 0.0;    // B_c, N*s/m
};

// Default coupling gains for a device ticking every `period` seconds.
//
// The device sees the coupling as a sampled spring-damper, so it must obey the passivity bound of
// a sampled wall, b > K_c T / 2 + B_c, with b the device's physical damping (Colgate & Schenkel
// 1997), and stay below the device's max stable stiffness. K_c takes 80 % of the smaller of the
// spec's max stable stiffness and the bound's K limit 2 b / T; B_c takes half of what the bound
// leaves, b - K_c T / 2, so the damping that settles the hand on the spring and the margin to the
// bound are equal. The 20 % and 50 % margins cover the uncertainty of the data-sheet damping.
FITFEEL_API CouplingGains DefaultCouplingGains(const DeviceSpec& spec, double period);
// True when the gains obey K_c <= max_stiffness and b > K_c T / 2 + B_c.
FITFEEL_API bool CouplingGainsArePassive(const CouplingGains& gains, const DeviceSpec& spec,
                                         double period);

// The spring-damper between the device handle and the proxy (the simulated moving part), and the
// proxy's own motion under the environment's force, in device units.
//
// The proxy is advanced by backward Euler with the coupling and a local linearisation of the
// environment (stiffness k_e) taken implicitly:
//   m (v1 - v0) / T = F_e(x0) - k_e (x1 - x0) + K_c (x_d - x1) + B_c (v_d - v1),  x1 = x0 + T v1
// which is unconditionally stable for a linear environment whatever its stiffness (a press fit is
// orders of magnitude stiffer than any device), and reduces to a quasi-static proxy for m = 0.
// k_e is the larger of the hint the runtime gives (the contact stiffness, if it knows it) and a
// secant estimate from the last two (position, force) samples of the proxy that decays with a
// 0.1 s time constant once contact ends (long against the tick, short against a gesture). A
// secant taken across the environment's face underestimates a stiff wall, so on the step after
// contact begins or ends the proxy may move at most half-way back towards the previous position
// (bisection of the face); the proxy then settles with both samples inside, where the secant is
// exact (tested to 2e10 N/m without a hint).
class FITFEEL_API VirtualCoupling {
 public:
  void Configure(const CouplingGains& gains, double proxy_mass);
  // Puts the proxy at the handle, at rest, with no environment history.
  void Reset(const Eigen::Vector3d& device_position,
             const Eigen::Vector3d& device_velocity) noexcept;

  // Per tick: `environment_force` acted on the proxy at its current position (device newtons);
  // advances the proxy by `dt` and returns the force on the device handle.
  Eigen::Vector3d Step(const Eigen::Vector3d& environment_force,
                       const Eigen::Vector3d& device_position,
                       const Eigen::Vector3d& device_velocity, double stiffness_hint,
                       double dt) noexcept;

  const Eigen::Vector3d& proxy_position() const { return position_; }
  const Eigen::Vector3d& proxy_velocity() const { return velocity_; }
  double environment_stiffness() const { return stiffness_estimate_; }
  const CouplingGains& gains() const { return gains_; }

 private:
  CouplingGains gains_;
  double mass_ = 0.0;
  Eigen::Vector3d position_{0.0, 0.0, 0.0};
  Eigen::Vector3d velocity_{0.0, 0.0, 0.0};
  Eigen::Vector3d last_position_{0.0, 0.0, 0.0};
  Eigen::Vector3d last_force_{0.0, 0.0, 0.0};
  bool has_last_ = false;
  double stiffness_estimate_ = 0.0;
};

}  // namespace fitfeel
