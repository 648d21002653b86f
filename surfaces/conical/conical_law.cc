#include "surfaces/conical/conical_law.h"

#include <cmath>

#include "framework/core/error.h"
#include "framework/model/elastic_limit.h"
#include "surfaces/conical/conical_geometry.h"

namespace fitfeel::conical {

double LamePressurePerInterference(double d, double d2, const Material& pin, const Material& hub) {
  if (!(d > 0.0) || !(d2 > d)) throw UserError("Lame pressure needs 0 < d < d2");
  if (!(pin.youngs_modulus > 0.0) || !(hub.youngs_modulus > 0.0)) {
    throw UserError("Lame pressure needs positive Young's moduli");
  }
  const double hub_term =
      ((d2 * d2 + d * d) / (d2 * d2 - d * d) + hub.poisson) / hub.youngs_modulus;
  const double pin_term = (1.0 - pin.poisson) / pin.youngs_modulus;
  return (2.0 / d) / (pin_term + hub_term);
}

void TaperPressFitLaw::DoPrepare(const PartSpec& inner, const PartSpec& outer,
                                 const ModelSettings& settings) {
  const ConicalGeometry& hole = GeometryOf(outer);
  GeometryOf(inner);
  friction_ = StickSlipFriction(FrictionOf(settings));
  sin_alpha_ = std::sin(hole.half_angle());
  cos_alpha_ = std::cos(hole.half_angle());
  const double dm = hole.mean_diameter();
  mean_radius_ = 0.5 * dm;
  pressure_per_interference_ =
      LamePressurePerInterference(dm, hole.outer_diameter(), inner.material, outer.material);
  hub_yield_pressure_ = outer.material.yield_strength > 0.0
                            ? HubYieldPressure(dm, hole.outer_diameter(),
                                               outer.material.yield_strength)
                            : 0.0;
  pin_yield_pressure_ = inner.material.yield_strength > 0.0
                            ? ShaftYieldPressure(dm, 0.0, inner.material.yield_strength)
                            : 0.0;
}

double TaperPressFitLaw::Normal(const ContactState& contact, Wrench* out) const noexcept {
  out->SetZero();
  if (!contact.engaged || !(contact.interference_volume > 0.0)) return 0.0;
  const double normal = pressure_per_interference_ * contact.interference_volume;
  const double radial = pressure_per_interference_ * cos_alpha_;
  out->force.x() = -radial * contact.pressure_resultant.x();
  out->force.z() = -radial * contact.pressure_resultant.y();
  out->force.y() = -normal * sin_alpha_;
  return normal;
}

void TaperPressFitLaw::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                                  Wrench* out) const noexcept {
  const double normal = Normal(contact, out);
  // Slip on the cone: along the generatrix v_y cos(alpha) (the normal part v_y sin(alpha) is taken
  // up by the elastic interference), around it omega_y * rm.
  const Eigen::Vector2d slip(motion.velocity.y() * cos_alpha_,
                             motion.angular_velocity.y() * mean_radius_);
  const Eigen::Vector2d f = friction_.Smoothed(slip, normal);
  out->force.y() += f.x() * cos_alpha_;
  out->torque.y() = f.y() * mean_radius_;
}

void TaperPressFitLaw::DoEvaluateWithState(const ContactState& contact,
                                           const MatingMotion& motion, LawState* state,
                                           Wrench* out) const noexcept {
  const double normal = Normal(contact, out);
  const Eigen::Vector2d at(motion.depth * cos_alpha_, motion.angle * mean_radius_);
  const Eigen::Vector2d f = friction_.Step(at, normal, &state->friction);
  out->force.y() += f.x() * cos_alpha_;
  out->torque.y() = f.y() * mean_radius_;
}

bool TaperPressFitLaw::DoRadialJacobian(const ContactState& contact,
                                        Eigen::Matrix2d* jacobian) const noexcept {
  if (!contact.engaged || !(contact.interference_volume > 0.0)) return false;
  *jacobian = -(pressure_per_interference_ * cos_alpha_) * contact.resultant_jacobian;
  return true;
}

ElasticLimitCheck TaperPressFitLaw::DoCheckElasticLimit(
    const ContactState& contact) const noexcept {
  ElasticLimitCheck check;
  const double peak = pressure_per_interference_ * contact.max_interference;
  if (!(peak > 0.0)) return check;
  if (hub_yield_pressure_ > 0.0) {
    check.utilisation = peak / hub_yield_pressure_;
    check.part = 1;
  }
  if (pin_yield_pressure_ > 0.0 && peak / pin_yield_pressure_ > check.utilisation) {
    check.utilisation = peak / pin_yield_pressure_;
    check.part = 2;
  }
  return check;
}

}  // namespace fitfeel::conical
