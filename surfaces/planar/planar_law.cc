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
  friction_ = StickSlipFriction(FrictionOf(settings));
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

double PlanarGpsLaw::WallCompliance(double engaged_length) const noexcept {
  if (!(engaged_length > 0.0)) return 0.0;
  return wall_factor_ * RectangleSelfPotential(height_, engaged_length) /
         (height_ * engaged_length);
}

double PlanarGpsLaw::PressurePerInterferenceAt(double engaged_length) const noexcept {
  return 2.0 / (c_key_ + 2.0 * WallCompliance(engaged_length));
}

double PlanarGpsLaw::LateralStiffness(double engaged_length, double face_area,
                                      int faces_pressed) const noexcept {
  const double c_wall = WallCompliance(engaged_length);
  return c_wall > 0.0 ? faces_pressed * face_area / c_wall : 0.0;
}

double PlanarGpsLaw::Normal(const ContactState& contact, Wrench* out) const noexcept {
  out->SetZero();
  if (!contact.engaged) return 0.0;
  const double pressure = PressurePerInterferenceAt(contact.engaged_length);
  const double k =
      stiffness_ > 0.0 ? stiffness_
                       : LateralStiffness(contact.engaged_length, contact.engaged_area / faces_,
                                          contact.interference ? 2 : 1);
  const double lateral = k * contact.penetration;
  out->force.x() = -lateral * contact.penetration_direction.x();
  out->force.z() = -lateral * contact.penetration_direction.y();
  // In clearance V holds only texture tabulated at the interval's middle, a contact apart from
  // the flank the part rests on.
  const double pressed = pressure * contact.interference_volume;
  return contact.interference ? pressed : lateral + pressed;
}

void PlanarGpsLaw::AddTwistTorque(const ContactState& contact, double twist,
                                  Wrench* out) const noexcept {
  const double push = std::hypot(out->force.x(), out->force.z());
  if (!(push > 0.0) || !(std::abs(twist) > 0.0) || !std::isfinite(twist)) return;
  // Twisted by theta, a face's closure varies linearly across its height h, the penetration
  // being its most at the pressed edge. On a Winkler strip the push then acts at the centroid of
  // the closure: where only part of the face touches (penetration <= h theta) a third of the
  // touching width in from the edge; where all of it touches, h^2 theta / (12 c) off the centre
  // with c the closure at the centre. The two agree at penetration = h theta (h / 6), and the
  // lever falls to 0 as the twist does.
  const double h = height_, slope = std::abs(twist), depth = contact.penetration;
  const double lever = depth <= h * slope ? 0.5 * h - depth / (3.0 * slope)
                                          : slope * h * h / (12.0 * (depth - 0.5 * h * slope));
  // Against the twist: the pressed edge is the one the twist swings into the wall.
  out->torque.y() -= std::copysign(lever * push, twist);
}

void PlanarGpsLaw::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                              Wrench* out) const noexcept {
  const double normal = Normal(contact, out);
  AddTwistTorque(contact, motion.angle, out);
  out->force.y() = friction_.Smoothed({motion.velocity.y(), 0.0}, normal).x();
}

void PlanarGpsLaw::DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion,
                                       LawState* state, Wrench* out) const noexcept {
  const double normal = Normal(contact, out);
  AddTwistTorque(contact, motion.angle, out);
  out->force.y() = friction_.Step({motion.depth, 0.0}, normal, &state->friction).x();
}

}  // namespace fitfeel::planar
