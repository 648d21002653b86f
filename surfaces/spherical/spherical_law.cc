#include "surfaces/spherical/spherical_law.h"

#include <cmath>

#include "framework/core/error.h"
#include "surfaces/spherical/spherical_geometry.h"

namespace fitfeel::spherical {

double ThickShellPressurePerInterference(double a, double b, const Material& ball,
                                         const Material& shell) {
  if (!(a > 0.0) || !(b > a)) throw UserError("thick-shell pressure needs 0 < a < b");
  if (!(ball.youngs_modulus > 0.0) || !(shell.youngs_modulus > 0.0)) {
    throw UserError("thick-shell pressure needs positive Young's moduli");
  }
  const double a3 = a * a * a, b3 = b * b * b;
  const double ball_term = (1.0 - 2.0 * ball.poisson) / ball.youngs_modulus;
  const double shell_term = ((1.0 - 2.0 * shell.poisson) * a3 + (1.0 + shell.poisson) * b3 / 2.0) /
                            (shell.youngs_modulus * (b3 - a3));
  return 1.0 / (a * (ball_term + shell_term));
}

void KnuckleBearingLaw::DoPrepare(const PartSpec& inner, const PartSpec& outer,
                                  const ModelSettings& settings) {
  GeometryOf(inner);
  const SphericalGeometry& socket = GeometryOf(outer);
  mu_ = settings.friction;
  arm_ = socket.mean_axis_distance();
  pressure_per_interference_ = ThickShellPressurePerInterference(
      socket.radius(), 0.5 * socket.outer_diameter(), inner.material, outer.material);
}

void KnuckleBearingLaw::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                                   Wrench* out) const noexcept {
  out->SetZero();
  if (!(contact.interference_volume > 0.0)) return;
  const double normal = pressure_per_interference_ * contact.interference_volume;
  out->force.x() = -pressure_per_interference_ * contact.pressure_resultant.x();
  out->force.z() = -pressure_per_interference_ * contact.pressure_resultant.y();
  const double slip = motion.angular_velocity.y() * arm_;
  out->torque.y() = -mu_ * normal * arm_ * std::tanh(slip / kFrictionSmoothingVelocity);
}

}  // namespace fitfeel::spherical
