#include "surfaces/cylindrical/cylindrical_law.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "framework/core/error.h"
#include "surfaces/cylindrical/cylindrical_geometry.h"

namespace fitfeel::cylindrical {
namespace {

// Numbers in messages. snprintf rather than std::to_string, whose integer path instantiates a
// GNU-unique (exported) table in the plugin, and whose "%f" hides micrometres.
std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

const CylindricalGeometry& Cylinder(const PartSpec& part) {
  const auto* g = dynamic_cast<const CylindricalGeometry*>(part.geometry.get());
  if (g == nullptr) {
    throw UserError("part '" + part.name + "' has no cylindrical geometry for the press-fit law");
  }
  return *g;
}

void CheckMaterial(const PartSpec& part) {
  const Material& m = part.material;
  if (!(m.youngs_modulus > 0.0) || !(m.poisson >= 0.0 && m.poisson < 0.5)) {
    throw UserError("part '" + part.name +
                    "': the press-fit law needs a Young's modulus > 0 and 0 <= Poisson < 0.5");
  }
}

double Stiffness(double fixed, double pressure_per_interference, double d1, double length) {
  return fixed > 0.0 ? fixed : LameRadialStiffness(pressure_per_interference, d1, length);
}

double Friction(double mu, double normal, double velocity) {
  return -mu * normal * std::tanh(velocity / kFrictionSmoothingVelocity);
}

}  // namespace

PressFitDimensions PressFitDimensionsOf(const PartSpec& inner, const PartSpec& outer) {
  PressFitDimensions d;
  d.d1 = inner.size.nominal;
  d.d2 = Cylinder(outer).outer_diameter();
  d.di = Cylinder(inner).bore_diameter();
  if (!(d.d1 > 0.0) || !(d.d2 > d.d1) || !(d.di >= 0.0 && d.di < d.d1)) {
    throw UserError("press fit needs 0 <= shaft bore < shaft diameter < hub outer diameter (got " +
                    Num(d.di) + ", " + Num(d.d1) + ", " + Num(d.d2) + " m)");
  }
  return d;
}

double LamePressurePerInterference(const PressFitDimensions& d, const Material& shaft,
                                   const Material& hub) {
  const double d1s = d.d1 * d.d1, d2s = d.d2 * d.d2, dis = d.di * d.di;
  const double c_shaft = (d1s + dis) / (d1s - dis) - shaft.poisson;  // 1 - nu1 when di = 0
  const double c_hub = (d2s + d1s) / (d2s - d1s) + hub.poisson;
  return (2.0 / d.d1) / (c_shaft / shaft.youngs_modulus + c_hub / hub.youngs_modulus);
}

double LameRadialStiffness(double pressure_per_interference, double d1, double engaged_length) {
  return pressure_per_interference * std::numbers::pi * d1 * engaged_length / 2.0;
}

void GpsLaw::DoPrepare(const PartSpec& inner, const PartSpec& outer,
                       const ModelSettings& settings) {
  CheckMaterial(inner);
  CheckMaterial(outer);
  const PressFitDimensions d = PressFitDimensionsOf(inner, outer);
  mu_ = settings.friction;
  stiffness_ = settings.contact_stiffness;
  d1_ = d.d1;
  pressure_per_interference_ = LamePressurePerInterference(d, inner.material, outer.material);
}

void GpsLaw::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                        Wrench* out) const noexcept {
  out->SetZero();
  if (!contact.engaged) return;
  const double k = Stiffness(stiffness_, pressure_per_interference_, d1_, contact.engaged_length);
  const Eigen::Vector2d radial = -k * contact.penetration * contact.penetration_direction;
  const double pressure_sum = pressure_per_interference_ * contact.interference_volume;  // eq. 11
  const double normal = radial.norm() + pressure_sum;                                    // eq. 12
  out->force = Eigen::Vector3d(radial.x(), Friction(mu_, normal, motion.velocity.y()), radial.y());
}

void Ve1Law::DoPrepare(const PartSpec& inner, const PartSpec& outer,
                       const ModelSettings& settings) {
  CheckMaterial(inner);
  CheckMaterial(outer);
  const PressFitDimensions d = PressFitDimensionsOf(inner, outer);
  mu_ = settings.friction;
  stiffness_ = settings.contact_stiffness;
  d1_ = d.d1;
  pressure_per_interference_ = LamePressurePerInterference(d, inner.material, outer.material);
  clearance_ = 0.5 * (outer.size.nominal - inner.size.nominal);
  if (clearance_ < 0.0) clearance_ = 0.0;  // ideal geometry never interferes in VE1
}

void Ve1Law::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                        Wrench* out) const noexcept {
  out->SetZero();
  if (!contact.engaged) return;
  const double k = Stiffness(stiffness_, pressure_per_interference_, d1_, contact.engaged_length);
  const double penetration = std::max(0.0, contact.offset_distance - clearance_);
  const Eigen::Vector2d radial =
      -k * penetration *
      Eigen::Vector2d(std::cos(contact.offset_angle), std::sin(contact.offset_angle));
  out->force =
      Eigen::Vector3d(radial.x(), Friction(mu_, radial.norm(), motion.velocity.y()), radial.y());
}

}  // namespace fitfeel::cylindrical
