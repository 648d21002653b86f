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

// Radial contact stiffness when the scenario leaves k_p at 0 (auto): the Lame stiffness of the
// joint over the engaged length L. An axis offset e with all-round elastic contact gives the
// interference e*cos(theta), pressure P*e*cos(theta) with P the Lame pressure per unit
// interference, and the resultant integral of P e cos^2(theta) (d1/2) dtheta L = P e pi d1 L / 2.
double LameRadialStiffness(double pressure_per_interference, double d1, double engaged_length);

// What the cylinder's three laws share: the press fit of two thick-walled cylinders (Lame's
// pressure per unit interference, the joint's radial stiffness k_p or, left at 0, the Lame
// stiffness of the engaged length) and friction along the axis on a normal force each law
// defines: stick-slip on the depth with the run's state (framework/model/friction.h; at the
// paper's 10 mm/s it slides at mu_k N from the first micrometres), and without state the smoothed
// kinetic law mu_k N tanh(v_y / v_s).
class PressFitLaw : public ResistanceLaw {
 public:
  double pressure_per_interference() const { return pressure_per_interference_; }

 protected:
  // Checks both materials and the diameters, takes the friction and the stiffness from the
  // settings, then PrepareLaw.
  void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                 const ModelSettings& settings) final;
  void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                  Wrench* out) const noexcept final;
  void DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion, LawState* state,
                           Wrench* out) const noexcept final;

  // What a law prepares of its own. Default: nothing.
  virtual void PrepareLaw(const PartSpec& inner, const PartSpec& outer,
                          const PressFitDimensions& d);
  // For an engaged contact: the radial force on the moving part (x, z) from the joint's radial
  // stiffness `k`, and the normal force the axial friction acts on.
  virtual double Normal(const ContactState& contact, double k,
                        Eigen::Vector2d* radial) const noexcept = 0;

 private:
  // The radial force into `out` (zero unless engaged); returns the normal force.
  double RadialAndNormal(const ContactState& contact, Wrench* out) const noexcept;

  StickSlipFriction friction_;
  double stiffness_ = 0.0;  // 0: Lame stiffness of the engaged length
  double d1_ = 0.0;
  double pressure_per_interference_ = 0.0;
};

// The paper's law: eq. 9 without interference (radial spring on the penetration beyond the
// assembly space, axial Coulomb mu * |F_radial|); eqs. 10-12 with it (the spring holds the axis at
// the energy-minimising position, and the axial friction adds mu * sum p * ds, with sum p * ds the
// Lame pressure per unit interference times the analyzer's interference volume). Both terms are
// used in either state; each vanishes where the paper's other case applies, so the force is
// continuous across the clearance / interference boundary. Elastic limit (DIN 7190): the largest
// cell pressure against the hub's and the shaft's, for parts with a yield strength.
class GpsLaw final : public PressFitLaw {
 protected:
  void PrepareLaw(const PartSpec& inner, const PartSpec& outer,
                  const PressFitDimensions& d) override;
  // Eq. 12's normal force.
  double Normal(const ContactState& contact, double k,
                Eigen::Vector2d* radial) const noexcept override;
  ElasticLimitCheck DoCheckElasticLimit(const ContactState& contact) const noexcept override;
  double DoPressurePerInterference() const override { return pressure_per_interference(); }

 private:
  double hub_yield_pressure_ = 0.0;  // 0: no yield strength given
  double shaft_yield_pressure_ = 0.0;
};

// The elastic model (docs/contact-mechanics.md): the analyzer solves the contact pressure at the
// part's equilibrium (compliance per harmonic, non-negative pressure, offset and tilt free, DIN
// 7190 smoothing with texture din7190) and reports its normal force N = sum p A. Radially the
// part is held at that equilibrium by the joint's Lame radial stiffness (or k_p), as in the gps
// law; axially friction acts on the larger of N and the radial spring's force: a radial load
// carried by a part in all-round contact only shifts its pressure (the cos theta it adds
// integrates to zero), while one carried on a line of contact is the normal force itself. So the
// normal force is never counted twice (eq. 12 adds |F_radial| to sum p A).
class ElasticLaw final : public PressFitLaw {
 protected:
  double Normal(const ContactState& contact, double k,
                Eigen::Vector2d* radial) const noexcept override;
  double DoPressurePerInterference() const override { return pressure_per_interference(); }
};

// The paper's comparison method VE1: ideal geometry (nominal sizes, no form, no texture), constant
// Coulomb friction mu * radial load. The radial load is the spring force of the ideal bore: an
// axis offset beyond the nominal radial clearance (zero for equal nominal sizes) is pushed back
// with k_p. It ignores the analyzer's tolerance and assembly spaces on purpose.
class Ve1Law final : public PressFitLaw {
 protected:
  void PrepareLaw(const PartSpec& inner, const PartSpec& outer,
                  const PressFitDimensions& d) override;
  double Normal(const ContactState& contact, double k,
                Eigen::Vector2d* radial) const noexcept override;

 private:
  double clearance_ = 0.0;  // nominal radial clearance, m
};

}  // namespace fitfeel::cylindrical
