#pragma once

#include "framework/model/resistance_law.h"

namespace fitfeel::example_slide {

// Compliance per unit area (m/Pa) of an elastic block of width w compressed across it in plane
// strain (long along y, so it cannot stretch along y; free across its height): w (1 - nu^2) / E.
double BlockCompliance(double width, double youngs_modulus, double poisson);

// Coulomb friction regularised as mu N tanh(v / v_s): continuous through zero velocity, as the
// 1 kHz loop needs. v_s = 1 mm/s, the Stribeck range of steel on steel, below which a Coulomb law
// does not hold anyway.
inline constexpr double kFrictionSmoothingVelocity = 1e-3;

// The "spring" law (paper eqs. 9-12 for two flanks):
//  - lateral: the scene's contact stiffness k_p on the distance from the assembly space (eq. 9),
//    F_x = -k_p * penetration along penetration_direction;
//  - press fit: the block and the two rails are springs in series across x. A uniform interference
//    delta per flank (the block 2 delta wider than the slot) closes 2 delta over block + two rails:
//    p = P delta with P = 2 / (c_block + 2 c_rail), so sum(p ds) = P * interference_volume;
//  - axial, Coulomb friction on both: F_y = -mu (|F_x| + P V) tanh(v_y / v_s) (eq. 12).
class SlideSpringLaw final : public ResistanceLaw {
 protected:
  // Throws UserError for a material without a Young's modulus or Poisson's ratio in (-1, 0.5).
  void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                 const ModelSettings& settings) override;
  void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                  Wrench* out) const noexcept override;
  double DoPressurePerInterference() const override { return pressure_per_interference_; }

 private:
  double mu_ = 0.0;
  double stiffness_ = 0.0;
  double pressure_per_interference_ = 0.0;  // P, Pa/m
};

}  // namespace fitfeel::example_slide
