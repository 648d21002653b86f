#pragma once

#include <Eigen/Core>

#include "framework/core/export.h"

namespace fitfeel {

// Handbook coefficients of hard steel on hard steel (Marks' Standard Handbook for Mechanical
// Engineers, table "Coefficients of static and sliding friction"): dry, static 0.78 and sliding
// 0.42; greasy (lubricated), static 0.11-0.23 and sliding 0.029-0.12, of which the middles are
// taken. docs/friction.md says why and when a scene should name its own.
inline constexpr double kDrySteelStaticFriction = 0.78;
inline constexpr double kDrySteelKineticFriction = 0.42;
inline constexpr double kLubricatedSteelStaticFriction = 0.17;
inline constexpr double kLubricatedSteelKineticFriction = 0.075;

// Tangential displacement a steel junction takes before it breaks away: 2-5 um in the
// measurements summarised by Armstrong-Helouvry, Dupont and Canudas de Wit (Automatica 30(7),
// 1994, "presliding displacement"); the low end, since ground and reamed fits are smoother than
// the junctions measured there.
inline constexpr double kSteelBreakawayDisplacement = 2e-6;

// Velocity below which the stateless (history-free) friction is smoothed: the upper end of the
// Stribeck velocities of steel on steel (0.1-1 mm/s, same source).
inline constexpr double kFrictionSmoothingVelocity = 1e-3;

struct FrictionParameters {
  double static_coefficient = 0.0;   // mu_s: breakaway force / normal force
  double kinetic_coefficient = 0.0;  // mu_k <= mu_s: sliding force / normal force
  double breakaway_displacement = kSteelBreakawayDisplacement;  // z_s, m
};

// What a frictional contact carries from one tick to the next: where its junctions are anchored,
// in the contact's slip coordinates (m; a rotation enters as its arc length at the friction arm).
// Plain data owned by the run, not by the law: copy it to evaluate without advancing it.
struct FrictionState {
  Eigen::Vector2d anchor{0.0, 0.0};
  bool anchored = false;  // false until the first contact, and again while nothing is pressed
  bool sliding = false;   // the anchor was dragged in the last step
};

// Elasto-plastic stick-slip friction (the rate-independent limit of Dahl's model with a static
// and a kinetic level; the anchor formulation of Hayward and Armstrong, 2000; docs/friction.md).
// The junctions act as a tangential spring of stiffness k = mu_s N / z_s between the moving part
// and an anchor:
//  - sticking: F = -k (x - w); the anchor w stays, so the part is held at any push up to mu_s N
//    with a deflection of at most z_s;
//  - breakaway: when |x - w| would exceed z_s the junctions break and the anchor is dragged to
//    z_k = z_s mu_k / mu_s behind the part: F = mu_k N against the slip;
//  - sliding continues while the part keeps dragging the anchor beyond z_k; once it stops or
//    turns back the anchor stays and the contact sticks again (mu_s applies anew).
// The force depends on positions only, not on a measured velocity (no chatter at rest from
// velocity noise, no drift under vibration), and the element is passive: it stores at most
// mu_s N z_s / 2 in the spring and dissipates whatever drags the anchor.
class FITFEEL_API StickSlipFriction {
 public:
  StickSlipFriction() = default;  // frictionless
  // Throws UserError unless 0 <= mu_k <= mu_s and z_s > 0, all finite.
  explicit StickSlipFriction(const FrictionParameters& parameters);

  const FrictionParameters& parameters() const { return parameters_; }
  // Tangential stiffness of a sticking contact under the normal force `normal`, N/m.
  double StickingStiffness(double normal) const noexcept;

  // Per tick: the friction force on the moving part at slip position `position` (m) under the
  // normal force `normal` (N; <= 0 or not finite: no contact, the junctions are released), and
  // the state advanced to it. No allocation, no throw.
  Eigen::Vector2d Step(const Eigen::Vector2d& position, double normal,
                       FrictionState* state) const noexcept;

  // Without history (probes, a contact seen once): kinetic friction against the velocity,
  // mu_k N tanh(|v| / v_s), continuous through rest.
  Eigen::Vector2d Smoothed(const Eigen::Vector2d& velocity, double normal) const noexcept;

 private:
  FrictionParameters parameters_{0.0, 0.0, kSteelBreakawayDisplacement};
};

}  // namespace fitfeel
