#pragma once

#include <Eigen/Core>

#include "framework/core/export.h"

namespace fitfeel {

// Time-domain passivity observer and controller at the device port (Hannaford & Ryu 2002).
//
// The observer integrates the energy the rendering absorbs from the hand. The force F sent at one
// tick is held by the device until the next, while the handle moves by dx, so the work done on the
// hand over that interval is exactly F . dx; the energy absorbed is its negative. With
// credit_device_damping, the device's own damping b is credited with b |dx|^2 / T, a lower bound of
// the integral of b v^2 over the interval (Cauchy-Schwarz), so the credit never overstates it.
// For a sampled spring K held over T this gives exactly E = K x^2 / 2 + (b - K T / 2) sum |dx|^2 /
// T, i.e. the observer goes negative precisely when Colgate & Schenkel's bound b > K T / 2 is
// broken.
//
// A negative energy means the rendering created energy; energy_created() is the largest deficit
// seen. The optional controller adds a damping force -alpha v, alpha = -E / (T |v|^2) capped at
// max_damping, to dissipate the deficit over the next tick.
class FITFEEL_API PassivityObserver {
 public:
  void Configure(double device_damping, bool credit_device_damping, bool controller,
                 double max_damping);
  // Starts a new observation at `position` with no stored energy and no force held.
  void Reset(const Eigen::Vector3d& position) noexcept;

  // Per tick, first: accounts for the force held since the previous tick as the handle moved to
  // `position` over `dt` seconds.
  void Observe(const Eigen::Vector3d& position, double dt) noexcept;
  // Per tick: returns `force` plus the controller's damping force (if enabled and needed).
  Eigen::Vector3d Control(const Eigen::Vector3d& force, double dt) noexcept;
  // Per tick, last: the force actually sent, held until the next Observe.
  void Hold(const Eigen::Vector3d& force) noexcept { held_ = force; }

  double energy() const { return energy_; }                        // J absorbed; < 0: created
  double energy_created() const { return energy_created_; }        // J, largest deficit seen (>= 0)
  double controller_energy() const { return controller_energy_; }  // J the controller dissipated
  long controller_ticks() const { return controller_ticks_; }

 private:
  double device_damping_ = 0.0;
  bool credit_ = true;
  bool controller_ = false;
  double max_damping_ = 0.0;

  Eigen::Vector3d last_position_{0.0, 0.0, 0.0};
  Eigen::Vector3d last_displacement_{0.0, 0.0, 0.0};
  Eigen::Vector3d held_{0.0, 0.0, 0.0};
  bool started_ = false;
  double energy_ = 0.0;
  double energy_created_ = 0.0;
  double controller_energy_ = 0.0;
  long controller_ticks_ = 0;
};

}  // namespace fitfeel
