#include "surfaces/conical/conical_law.h"

#include <cmath>

#include "framework/core/error.h"
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
  mu_ = settings.friction;
  sin_alpha_ = std::sin(hole.half_angle());
  cos_alpha_ = std::cos(hole.half_angle());
  const double dm = hole.mean_diameter();
  mean_radius_ = 0.5 * dm;
  pressure_per_interference_ =
      LamePressurePerInterference(dm, hole.outer_diameter(), inner.material, outer.material);
}

void TaperPressFitLaw::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                                  Wrench* out) const noexcept {
  out->SetZero();
  if (!contact.engaged || !(contact.interference_volume > 0.0)) return;
  const double normal = pressure_per_interference_ * contact.interference_volume;
  const double radial = pressure_per_interference_ * cos_alpha_;
  out->force.x() = -radial * contact.pressure_resultant.x();
  out->force.z() = -radial * contact.pressure_resultant.y();
  out->force.y() = -normal * sin_alpha_;
  // Slip on the cone: along the generatrix v_y cos(alpha) (the normal part v_y sin(alpha) is taken
  // up by the elastic interference), around it omega_y * rm.
  const double v_slide = motion.velocity.y() * cos_alpha_;
  const double v_turn = motion.angular_velocity.y() * mean_radius_;
  const double speed = std::hypot(v_slide, v_turn);
  // tanh(speed / v_s) / speed, continuous at zero speed (limit 1 / v_s).
  const double per_speed = speed > 1e-12 * kFrictionSmoothingVelocity
                               ? std::tanh(speed / kFrictionSmoothingVelocity) / speed
                               : 1.0 / kFrictionSmoothingVelocity;
  const double friction = mu_ * normal * per_speed;
  out->force.y() -= friction * cos_alpha_ * v_slide;
  out->torque.y() = -friction * v_turn * mean_radius_;
}

}  // namespace fitfeel::conical
