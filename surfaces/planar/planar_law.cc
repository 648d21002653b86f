#include "surfaces/planar/planar_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "framework/core/error.h"
#include "surfaces/planar/planar_geometry.h"

namespace fitfeel::planar {

double BlockCompliance(double width, double youngs_modulus, double poisson) {
  return width * (1.0 - poisson * poisson) / youngs_modulus;
}

double RectangleSelfPotential(double a, double b) {
  if (!(a > 0.0) || !(b > 0.0)) return 0.0;
  const double d = std::hypot(a, b);
  return (2.0 / 3.0) * (a * a * a + b * b * b - d * d * d) +
         2.0 * a * b * (a * std::asinh(b / a) + b * std::asinh(a / b));
}

double HalfSpaceStripCompliance(double height, double length, double youngs_modulus,
                                double poisson) {
  if (!(height > 0.0) || !(length > 0.0)) return 0.0;
  return (1.0 - poisson * poisson) * RectangleSelfPotential(height, length) /
         (std::numbers::pi * youngs_modulus * height * length);
}

double PressurePerInterference(double width, double height, double length, double e_key,
                               double nu_key, double e_wall, double nu_wall) {
  return 2.0 / (BlockCompliance(width, e_key, nu_key) +
                2.0 * HalfSpaceStripCompliance(height, length, e_wall, nu_wall));
}

void PlanarGpsLaw::DoPrepare(const PartSpec& inner, const PartSpec& outer,
                             const ModelSettings& settings) {
  const PlanarGeometry& g = PlanarGeometryOf(inner);
  for (const PartSpec* p : {&inner, &outer}) {
    if (!(p->material.youngs_modulus > 0.0) || !PoissonInRange(p->material.poisson)) {
      throw UserError("part '" + p->name + "': the planar law needs a Young's modulus and a " +
                      "Poisson's ratio in [0, 0.5)");
    }
  }
  mu_ = settings.friction;
  stiffness_ = settings.contact_stiffness;
  c_key_ = BlockCompliance(g.width(), inner.material.youngs_modulus, inner.material.poisson);
  height_ = g.height();
  wall_factor_ = (1.0 - outer.material.poisson * outer.material.poisson) /
                 (std::numbers::pi * outer.material.youngs_modulus);
  faces_ = g.faces();
  full_length_ = std::min(g.length(), PlanarGeometryOf(outer).length());
}

double PlanarGpsLaw::DoPressurePerInterference() const {
  return PressurePerInterferenceAt(full_length_);
}

double PlanarGpsLaw::PressurePerInterferenceAt(double engaged_length) const noexcept {
  double c_wall = 0.0;
  if (engaged_length > 0.0) {
    c_wall =
        wall_factor_ * RectangleSelfPotential(height_, engaged_length) / (height_ * engaged_length);
  }
  return 2.0 / (c_key_ + 2.0 * c_wall);
}

void PlanarGpsLaw::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                              Wrench* out) const noexcept {
  out->SetZero();
  if (!contact.engaged) return;
  const double pressure = PressurePerInterferenceAt(contact.engaged_length);
  const double k = stiffness_ > 0.0 ? stiffness_ : pressure * contact.engaged_area / faces_;
  const double lateral = k * contact.penetration;
  out->force.x() = -lateral * contact.penetration_direction.x();
  out->force.z() = -lateral * contact.penetration_direction.y();
  const double normal = lateral + pressure * contact.interference_volume;
  out->force.y() = -mu_ * normal * std::tanh(motion.velocity.y() / kFrictionSmoothingVelocity);
}

}  // namespace fitfeel::planar
