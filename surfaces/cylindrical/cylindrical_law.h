#pragma once

#include "framework/model/resistance_law.h"

namespace fitfeel::cylindrical {

// Diameters that enter the thick-walled cylinder solution, from both parts' specs.
struct PressFitDimensions {
  double d1 = 0.0;  // mating (shaft) diameter, m
  double d2 = 0.0;  // hub outer diameter, m
  double di = 0.0;  // bore of a hollow shaft, m (0 = solid)
};

// Reads d1 (the inner part's nominal size), d2 and di (the parts' CylindricalGeometry); throws
// UserError when a part has no cylindrical geometry or the diameters do not nest.
PressFitDimensions PressFitDimensionsOf(const PartSpec& inner, const PartSpec& outer);

// Contact pressure per unit radial interference, Pa/m (paper eq. 10, docs/oracles.md):
// p = (2 delta / d1) / ( c_shaft / E1 + ((d2^2 + d1^2)/(d2^2 - d1^2) + nu2) / E2 ),
// c_shaft = 1 - nu1 for a solid shaft, (d1^2 + di^2)/(d1^2 - di^2) - nu1 for a hollow one.
double LamePressurePerInterference(const PressFitDimensions& d, const Material& shaft,
                                   const Material& hub);

// Coulomb friction is regularised as mu * N * tanh(v / v_s) so that it is continuous through
// zero velocity. v_s = 1 mm/s is the upper end of the Stribeck velocities reported for
// steel-on-steel (0.1-1 mm/s, Armstrong-Helouvry, Dupont and Canudas de Wit, Automatica 1994):
// below it friction is in the pre-sliding / mixed regime that a Coulomb law does not describe
// anyway, so the smoothing alters no regime the model claims; at the paper's 10 mm/s it is
// Coulomb to 1e-8.
inline constexpr double kFrictionSmoothingVelocity = 1e-3;

// Radial contact stiffness when the scenario leaves k_p at 0 (auto): the Lame stiffness of the
// joint over the engaged length L. An axis offset e with all-round elastic contact gives the
// interference e*cos(theta), pressure P*e*cos(theta) with P the Lame pressure per unit
// interference, and the resultant integral of P e cos^2(theta) (d1/2) dtheta L = P e pi d1 L / 2.
double LameRadialStiffness(double pressure_per_interference, double d1, double engaged_length);

// The paper's law: eq. 9 without interference (radial spring on the penetration beyond the
// assembly space, axial Coulomb mu * |F_radial|); eqs. 10-12 with it (the spring holds the axis at
// the energy-minimising position, and the axial friction adds mu * sum p * ds, with sum p * ds the
// Lame pressure per unit interference times the analyzer's interference volume). Both terms are
// used in either state; each vanishes where the paper's other case applies, so the force is
// continuous across the clearance / interference boundary.
class GpsLaw final : public ResistanceLaw {
 public:
  double pressure_per_interference() const { return pressure_per_interference_; }

 protected:
  void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                 const ModelSettings& settings) override;
  void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                  Wrench* out) const noexcept override;
  double DoPressurePerInterference() const override { return pressure_per_interference_; }

 private:
  double mu_ = 0.0;
  double stiffness_ = 0.0;  // 0: Lame stiffness of the engaged length
  double d1_ = 0.0;
  double pressure_per_interference_ = 0.0;
};

// The paper's comparison method VE1: ideal geometry (nominal sizes, no form, no texture), constant
// Coulomb friction mu * radial load. The radial load is the spring force of the ideal bore: an
// axis offset beyond the nominal radial clearance (zero for equal nominal sizes) is pushed back
// with k_p. It ignores the analyzer's tolerance and assembly spaces on purpose.
class Ve1Law final : public ResistanceLaw {
 protected:
  void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                 const ModelSettings& settings) override;
  void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                  Wrench* out) const noexcept override;

 private:
  double mu_ = 0.0;
  double stiffness_ = 0.0;
  double d1_ = 0.0;
  double pressure_per_interference_ = 0.0;
  double clearance_ = 0.0;  // nominal radial clearance, m
};

}  // namespace fitfeel::cylindrical
