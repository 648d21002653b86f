#pragma once

#include "framework/model/gps_spec.h"
#include "framework/model/resistance_law.h"

namespace fitfeel::conical {

// Contact pressure per unit radial interference of a solid pin of diameter d in a thick-walled hub
// of outer diameter d2 (Lame, the paper's eq. 10, docs/oracles.md), Pa/m:
//   p / delta = (2 / d) / ( (1 - nu1)/E1 + ((d2^2 + d^2)/(d2^2 - d^2) + nu2)/E2 ).
double LamePressurePerInterference(double d, double d2, const Material& pin, const Material& hub);

// Taper press fit (DIN 7190). Each cell's pressure is p = P * delta with P the Lame pressure per
// unit interference at the hole's mean diameter dm (DIN 7190 evaluates the taper at dm; over a 1:50
// taper of a 20 mm hub the local diameter varies by +-2.5 %, P by less), so the summed normal
// force is N = P * sum(delta * ds) over the slant cell areas ds. On the pin:
//   wedge (axial part of the normal force): F_y = -N sin(alpha)   (pushes the pin out)
//   friction: -mu N cos(alpha) along the axial sliding, -mu N rm about the axis when it turns,
//             split by the direction of the combined sliding velocity (v_y, omega_y * rm)
//   radial:   F_(x,z) = -P cos(alpha) * sum(delta * ds * u_j)
// With a uniform interference over the hole's length L: N = p pi dm L / cos(alpha), so
//   F_in  = N (sin a + mu cos a) = p pi dm L (mu + tan a)
//   F_out = N (mu cos a - sin a) = p pi dm L (mu - tan a)      (DIN 7190, docs/oracles.md)
// Friction is stick-slip (framework/model/friction.h) with the run's state, in the slip
// coordinates (depth cos(alpha), angle * rm): a pin released in a taper with tan(alpha) < mu_s
// stays in (the junctions carry the wedge force N sin(alpha) up to mu_s N cos(alpha)). Without
// state (probes) it is the smoothed kinetic law along the sliding velocity.
// Elastic limit (DIN 7190, framework/model/elastic_limit.h): the largest cell pressure P * delta
// against the hub's bore limit at dm and the solid pin's, for parts with a yield strength.
// The returned wrench acts on the pin (the inner part), in the hole's mating frame.
class TaperPressFitLaw final : public ResistanceLaw {
 public:
  double pressure_per_interference() const { return pressure_per_interference_; }

 protected:
  // The Lame coefficient at the hole's mean diameter, the one every cell's pressure uses.
  double DoPressurePerInterference() const override { return pressure_per_interference_; }
  void DoPrepare(const PartSpec& inner, const PartSpec& outer,
                 const ModelSettings& settings) override;
  void DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                  Wrench* out) const noexcept override;
  void DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion,
                           LawState* state, Wrench* out) const noexcept override;
  ElasticLimitCheck DoCheckElasticLimit(const ContactState& contact) const noexcept override;
  // The radial force is -P cos(alpha) times the pressure resultant (Normal).
  bool DoRadialJacobian(const ContactState& contact,
                        Eigen::Matrix2d* jacobian) const noexcept override;

 private:
  // The normal (wedge) and radial parts of the wrench; returns the normal force N.
  double Normal(const ContactState& contact, Wrench* out) const noexcept;

  StickSlipFriction friction_;
  double hub_yield_pressure_ = 0.0;  // 0: no yield strength given
  double pin_yield_pressure_ = 0.0;
  double sin_alpha_ = 0.0;
  double cos_alpha_ = 0.0;
  double mean_radius_ = 0.0;
  double pressure_per_interference_ = 0.0;
};

}  // namespace fitfeel::conical
