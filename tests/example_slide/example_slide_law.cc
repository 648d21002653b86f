#include "tests/example_slide/example_slide_law.h"

#include <cmath>

#include "framework/core/error.h"
#include "tests/example_slide/example_slide_geometry.h"

namespace fitfeel::example_slide {

double BlockCompliance(double width, double youngs_modulus, double poisson) {
  return width * (1.0 - poisson * poisson) / youngs_modulus;
}

void SlideSpringLaw::DoPrepare(const PartSpec& inner, const PartSpec& outer,
                               const ModelSettings& settings) {
  for (const PartSpec* p : {&inner, &outer}) {
    if (!(p->material.youngs_modulus > 0.0) || !(p->material.poisson > -1.0) ||
        !(p->material.poisson < 0.5)) {
      throw UserError("part '" + p->name +
                      "': the spring law needs a Young's modulus and a Poisson's ratio in "
                      "(-1, 0.5)");
    }
  }
  mu_ = settings.friction;
  stiffness_ = settings.contact_stiffness;
  const double c_block = BlockCompliance(SlideGeometryOf(inner).width(),
                                         inner.material.youngs_modulus, inner.material.poisson);
  const double c_rail = BlockCompliance(SlideGeometryOf(outer).rail_width(),
                                        outer.material.youngs_modulus, outer.material.poisson);
  pressure_per_interference_ = 2.0 / (c_block + 2.0 * c_rail);
}

void SlideSpringLaw::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                                Wrench* out) const noexcept {
  out->SetZero();
  if (!contact.engaged) return;
  const double lateral = stiffness_ * contact.penetration;
  out->force.x() = -lateral * contact.penetration_direction.x();
  out->force.z() = -lateral * contact.penetration_direction.y();
  const double normal = lateral + pressure_per_interference_ * contact.interference_volume;
  out->force.y() = -mu_ * normal * std::tanh(motion.velocity.y() / kFrictionSmoothingVelocity);
}

}  // namespace fitfeel::example_slide
