#pragma once

#include <limits>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/core/wrench.h"
#include "framework/device/device.h"
#include "framework/runtime/part_state.h"
#include "framework/scenario/part_motion_settings.h"

namespace fitfeel {

// What the radial dynamics remember from tick to tick: part of the run's state (RunState).
struct PartMotionState {
  bool floating = false;               // integrated last tick (else held at the device's pose)
  Eigen::Vector2d position{0.0, 0.0};  // (x, z) of the leading end, m
  Eigen::Vector2d velocity{0.0, 0.0};  // m/s
  // The contact of the previous tick: its anchor (valid while in contact) and, for one free tick,
  // its plane; the slope used to step.
  Eigen::Vector2d previous_anchor{0.0, 0.0};
  bool has_anchor = false;
  Eigen::Vector2d plane_point{0.0, 0.0};
  Eigen::Vector2d plane_normal{0.0, 0.0};
  double plane_stiffness = 0.0;
  bool plane_valid = false;
  double previous_stiffness = 0.0;  // N/m
};

// What the stage tells the part's radial dynamics about the contact after a tick.
struct ContactFeedback {
  double stiffness = 0.0;  // of the contact behind the wrench, N/m; 0 when free
  // Free way (m) along the unit direction in the (x, z) cross-section before the part touches;
  // infinity: unknown.
  double gap = std::numeric_limits<double>::infinity();
  Eigen::Vector2d gap_direction{0.0, 0.0};
};

// The moving part's radial motion, framework side (CHAI3D's tool, as opposed to its device):
// immutable after construction, its per-run state passed in.
//
// Dynamic: integration is semi-implicit (symplectic) Euler with the damping c and the contact
// stiffness k taken implicitly:
//   v' = (m v + h (F + W)) / (m + h c + h^2 k),   x' = x + h v'.
// Free (k = 0) this is symplectic Euler, which keeps an oscillator's energy bounded where explicit
// Euler pumps it up and implicit Euler bleeds it away. In contact the force of the next position is
// linearised as F - k (x' - x): without that, a contact of stiffness k on the mass m sampled at
// period h is stable only while k < (4 + 2 h c / m) m / h^2 (ExplicitStabilityBound: 0.82 N/um for
// a 2 N shaft at 1 kHz), and a steel press fit is about 3.7 N/nm: its natural frequency (~21 kHz)
// is far above the tick's, so the part must reach its equilibrium within a tick, which the
// linearised step does (for m << h^2 k it is a Newton step to F = -W).
//
// The contact is not still: as the part advances, the position the contact holds it at moves with
// depth, and a step that assumed it fixed would lag it by a tick, which a stiff contact turns into
// a large spurious force (k times the anchor's travel per tick). With F = -k (x - a) the anchor is
// a = x + F / k, read off each tick and extrapolated linearly to the next. A free tick right after
// a contact tick keeps that contact as a one-sided plane for the step: a free fall of one tick is
// g h^2 = 9.8 um, deeper than most fits' clearance. When the stage says how far the free way
// reaches (ContactFeedback::gap), the surface there is such a plane too.
class FITFEEL_API PartMotion {
 public:
  // Throws UserError for a period or damping out of range.
  PartMotion(const PartMotionSettings& settings, double period);

  const PartMotionSettings& settings() const { return settings_; }
  PartMotionState MakeState() const { return PartMotionState{}; }

  // Per tick, after the device's Read: the part's state as the stages see it, from the device's
  // commanded pose, the scene's load and the radial state. Held: the device's pose without a load
  // to settle; quasi-static: with the load once the part is inside; dynamic: with the integrated
  // (x, z) position and velocity once the part floats.
  void Place(const DeviceState& device, const PartMotionState& state,
             PartState* part) const noexcept;
  // Per tick, after the wrench: advances the radial state by one period under the rendered wrench
  // (as delivered to the device) and the load. Nothing to do unless dynamic.
  void Step(const DeviceState& device, const Wrench& wrench, const ContactFeedback& contact,
            PartMotionState* state) const noexcept;

  // The load (x, z, N) acting on the part with the device at `device`: the scene's radial load
  // along -z once the leading end is past the entrance, else none (the holder carries the part).
  Eigen::Vector2d LoadAt(const DeviceState& device) const noexcept {
    return device.position.y() >= 0.0 ? Eigen::Vector2d(0.0, -settings_.radial_load)
                                      : Eigen::Vector2d(0.0, 0.0);
  }
  // The part's mass under that load, kg (0: no load, held).
  double MassAt(const DeviceState& device) const noexcept {
    return LoadAt(device).norm() / kStandardGravity;
  }
  // Largest contact stiffness an explicit contact force keeps stable on `mass` at the period, N/m:
  // what applies when the stiffness is not taken implicitly. Infinite without mass.
  double ExplicitStabilityBound(double mass) const;

 private:
  PartMotionSettings settings_;
  double period_;
};

}  // namespace fitfeel
