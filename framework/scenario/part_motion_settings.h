#pragma once

#include <cstddef>
#include <numbers>
#include <vector>

namespace fitfeel {

// Standard gravity (CGPM 1901), m/s^2: turns the part's weight into its mass.
inline constexpr double kStandardGravity = 9.80665;

// How the moving part moves across the mating axis (the scene's `part_motion` section). Along the
// axis (and about it) the part is where the device puts it; across it the device reports only the
// pose it commands, and the scene says what load acts on the part (its weight, which the holder
// lets act once the part's leading end is inside: the paper's robot) and what becomes of both.
enum class RadialMotion {
  // The part is where the device says: the holder takes any load (a hand at a haptic device).
  kHeld,
  // The constrained stage places the part each tick where the rendered radial force balances the
  // load (no radial dynamics): the paper's case study, whose shaft settles onto the bore under its
  // weight. With no load (or outside), as held.
  kQuasiStatic,
  // The part floats: its weight and the rendered radial force move the mass m = load / g
  // (semi-implicit Euler, the contact stiffness taken implicitly; framework/runtime/part_motion.h).
  // With no load, or before the entrance (where the holder carries the part), as held.
  kDynamic,
};

// The largest radial damping a scene may give, N*s/m: it stops a 1 kg part within a microsecond,
// beyond which nothing moves.
inline constexpr double kMaxPartDamping = 1e6;
// The largest radial load a scene may give, N.
inline constexpr double kMaxRadialLoad = 1e4;

// How the moving part turns about the mating axis (several-feature scenes).
enum class RotationMotion {
  // At the device's twist (a device that senses it; otherwise none): the holder takes the torque.
  kHeld,
  // The part turns where the contact's torque balances the applied torque (quasi-static).
  kFree,
};

// A torque about the mating axis at a time (N*m at s); between points it varies linearly, after
// the last it stays.
struct TorquePoint {
  double time = 0.0;
  double torque = 0.0;
};

// The largest torque a scene may apply about the axis, N*m (a hand's grip turns a few N*m; a
// wrench some hundreds).
inline constexpr double kMaxAppliedTorque = 1e4;

// What stops a scripted wrench turning a screw (ScrewTurn).
enum class TurnTarget {
  kNone,     // turns to the end of the run
  kTorque,   // the torque it applies reaches the value, N*m
  kAngle,    // the angle turned since the bearing face met reaches the value, rad
  kPreload,  // the bolt's tension reaches the value, N
};

// A screw turned by a scripted wrench (a thread scene's `part_motion.turn`): about +y at a
// constant speed from the start of engagement until the target, then held.
struct ScrewTurn {
  double speed = 0.0;  // rad/s; 0: the part keeps the device's twist (a hand turns it)
  TurnTarget target = TurnTarget::kNone;
  double value = 0.0;
};

// The largest turning speed a scene may give a wrench, rad/s (ten turns a second).
inline constexpr double kMaxTurnSpeed = 20.0 * std::numbers::pi;

struct PartMotionSettings {
  RadialMotion radial = RadialMotion::kQuasiStatic;
  double damping = 0.0;  // viscous damping of the part's radial motion, N*s/m (dynamic)
  // The load across the axis, N, along the scene's -z (down), acting once the part's leading end
  // is past the entrance (y >= 0): before it the holder carries the part.
  double radial_load = 0.0;
  RotationMotion rotation = RotationMotion::kHeld;
  // Applied about +y while the rotation is free (empty: none), times increasing.
  std::vector<TorquePoint> torque;
  // Screw scenes: the wrench, and the axial load on the moving part along +y (into the joint), N,
  // that keeps it on its flanks while it runs free.
  ScrewTurn turn;
  double axial_load = 0.0;
  // The tilt a robot holds the part at, about the scene's x axis, rad (a crooked start).
  double tilt = 0.0;
  // Where a hand holds a screw, m from the axis (fingers on a nut's flats, a wrench's handle): the
  // hand's twist turns the part through a torsional spring of its coupling's stiffness times
  // this squared. 0: the part takes the device's twist rigidly.
  double grip_lever = 0.0;
};

// The applied torque at `time` (N*m): linear between the points, the last one's after them, the
// first one's before; 0 without points. Allocates nothing.
inline double TorqueAt(const std::vector<TorquePoint>& points, double time) noexcept {
  if (points.empty()) return 0.0;
  if (time <= points.front().time) return points.front().torque;
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (time <= points[i].time) {
      const TorquePoint &a = points[i - 1], &b = points[i];
      const double span = b.time - a.time;
      return span > 0.0 ? a.torque + (b.torque - a.torque) * (time - a.time) / span : b.torque;
    }
  }
  return points.back().torque;
}

}  // namespace fitfeel
