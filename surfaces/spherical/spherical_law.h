#pragma once

#include "framework/model/gps_spec.h"
#include "framework/model/resistance_law.h"

namespace fitfeel::spherical {

// Contact pressure per unit radial interference of a solid ball of radius a in a thick spherical
// shell of outer radius b (Lame's solution for spheres, docs/oracles.md), Pa/m:
//   p / delta = 1 / ( a [ (1 - 2 nu1)/E1 + ((1 - 2 nu2) a^3 + (1 + nu2) b^3 / 2) / (E2 (b^3 - a^3))
//   ] )
// The inner ring of a real bearing has a cylindrical bore; it is taken as a solid ball (its bore
// stiffens nothing the spherical solution could describe, and the ring is much stiffer than the
// outer ring's shell, which dominates the compliance).
double ThickShellPressurePerInterference(double a, double b, const Material& ball,
                                         const Material& shell);

// Friction regularised as mu * N * tanh(|v| / v_s), v_s = 1 mm/s (the cylindrical and conical
// plugins' choice: the upper end of steel-on-steel Stribeck velocities, Armstrong-Helouvry et al.,
// Automatica 1994).
inline constexpr double kFrictionSmoothingVelocity = 1e-3;

// Knuckle (spherical plain) bearing. Each socket cell's pressure is p = P * delta (P above), so
// sum p ds = P * interference_volume. On the ball:
//   radial force   F_(x,z) = -P * sum(delta * ds * n_(x,z))    (pushes the centre back)
//   friction torque about the bearing axis, for the rotation omega_y:
//                  T_y = -mu * P * interference_volume * rho * tanh(|omega_y| rho / v_s)
//                  sign(omega_y)
// with rho the band's mean distance from the axis, (1/B) * integral of sqrt(a^2 - y^2) dy. For a
// uniform pressure this is exactly mu * integral of p * (distance from the axis) ds; a cell's arm
// is a cos(latitude), not a, so mu * sum p ds * a overstates the torque (by 3 % for GE 20 E's
// outer ring). Under a radial load the pressure concentrates in azimuth, not in latitude, so rho
// stays a close arm (the law sees only the analyzer's sums, not each cell).
// Tilting (omega_x, omega_z) and the axial force are not modelled: the bearing's mating motion is
// the rotation about its axis, and the ball is captive along it.
class KnuckleBearingLaw final : public ResistanceLaw {
 public:
  double pressure_per_interference() const { return pressure_per_interference_; }
  double friction_arm() const { return arm_; }

 protected:
  // The thick-shell coefficient every socket cell's pressure uses.
  double DoPressurePerInterference() const override { return pressure_per_interference_; }
  void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                 const ModelSettings& settings) override;
  void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                  Wrench* out) const noexcept override;

 private:
  double mu_ = 0.0;
  double arm_ = 0.0;
  double pressure_per_interference_ = 0.0;
};

}  // namespace fitfeel::spherical
