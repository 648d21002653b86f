#include "surfaces/cylindrical/cylindrical_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "framework/core/error.h"
#include "framework/core/number_text.h"
#include "framework/model/elastic_limit.h"
#include "surfaces/cylindrical/cylindrical_geometry.h"

namespace fitfeel::cylindrical {
namespace {

const CylindricalGeometry& Cylinder(const PartSpec& part) {
  const auto* g = dynamic_cast<const CylindricalGeometry*>(part.geometry.get());
  if (g == nullptr) {
    throw UserError("part '" + part.name + "' has no cylindrical geometry for the press-fit law");
  }
  return *g;
}

void CheckMaterial(const PartSpec& part) {
  const Material& m = part.material;
  if (!(m.youngs_modulus > 0.0) || !PoissonInRange(m.poisson)) {
    throw UserError("part '" + part.name +
                    "': the press-fit law needs a Young's modulus > 0 and 0 <= Poisson < 0.5");
  }
}

double Stiffness(double fixed, double pressure_per_interference, double d1, double length) {
  return fixed > 0.0 ? fixed : LameRadialStiffness(pressure_per_interference, d1, length);
}

}  // namespace

PressFitDimensions PressFitDimensionsOf(const PartSpec& inner, const PartSpec& outer) {
  PressFitDimensions d;
  d.d1 = inner.size.nominal;
  d.d2 = Cylinder(outer).outer_diameter();
  d.di = Cylinder(inner).bore_diameter();
  if (!(d.d1 > 0.0) || !(d.d2 > d.d1) || !(d.di >= 0.0 && d.di < d.d1)) {
    throw UserError("press fit needs 0 <= shaft bore < shaft diameter < hub outer diameter (got " +
                    MessageNumber(d.di) + ", " + MessageNumber(d.d1) + ", " + MessageNumber(d.d2) +
                    " m)");
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

void PressFitLaw::DoPrepare(const PartSpec& inner, const PartSpec& outer,
                            const ModelSettings& settings) {
  CheckMaterial(inner);
  CheckMaterial(outer);
  const PressFitDimensions d = PressFitDimensionsOf(inner, outer);
  friction_ = StickSlipFriction(FrictionOf(settings));
  stiffness_ = settings.contact_stiffness;
  d1_ = d.d1;
  pressure_per_interference_ = LamePressurePerInterference(d, inner.material, outer.material);
  PrepareLaw(inner, outer, d);
}

void PressFitLaw::PrepareLaw(const PartSpec&, const PartSpec&, const PressFitDimensions&) {}

double PressFitLaw::RadialAndNormal(const ContactState& contact, Wrench* out) const noexcept {
  out->SetZero();
  if (!contact.engaged) return 0.0;
  const double k = Stiffness(stiffness_, pressure_per_interference_, d1_, contact.engaged_length);
  Eigen::Vector2d radial;
  const double normal = Normal(contact, k, &radial);
  out->force.x() = radial.x();
  out->force.z() = radial.y();
  // A compliant holder's tilt forced towards the axis: the two contacts' couple turns the part,
  // and their normal forces add to what friction acts on.
  out->torque.x() = contact.couple_moment.x();
  out->torque.z() = contact.couple_moment.y();
  return normal + contact.couple_normal;
}

void PressFitLaw::DoEvaluate(const ContactState& contact, const MatingMotion& motion,
                             Wrench* out) const noexcept {
  const double normal = RadialAndNormal(contact, out);
  out->force.y() = friction_.Smoothed({motion.velocity.y(), 0.0}, normal).x();
}

void PressFitLaw::DoEvaluateWithState(const ContactState& contact, const MatingMotion& motion,
                                      LawState* state, Wrench* out) const noexcept {
  const double normal = RadialAndNormal(contact, out);
  out->force.y() = friction_.Step({motion.depth, 0.0}, normal, &state->friction).x();
}

void GpsLaw::PrepareLaw(const PartSpec& inner, const PartSpec& outer, const PressFitDimensions& d) {
  const double hub_re = outer.material.yield_strength, shaft_re = inner.material.yield_strength;
  hub_yield_pressure_ = hub_re > 0.0 ? HubYieldPressure(d.d1, d.d2, hub_re) : 0.0;
  shaft_yield_pressure_ = shaft_re > 0.0 ? ShaftYieldPressure(d.d1, d.di, shaft_re) : 0.0;
}

double GpsLaw::Normal(const ContactState& contact, double k,
                      Eigen::Vector2d* radial) const noexcept {
  *radial = -k * contact.penetration * contact.penetration_direction;
  const double pressure_sum = pressure_per_interference() * contact.interference_volume;  // eq. 11
  return radial->norm() + pressure_sum;                                                   // eq. 12
}

ElasticLimitCheck GpsLaw::DoCheckElasticLimit(const ContactState& contact) const noexcept {
  ElasticLimitCheck check;
  const double peak = pressure_per_interference() * contact.max_interference;
  if (!(peak > 0.0)) return check;
  if (hub_yield_pressure_ > 0.0) {
    check.utilisation = peak / hub_yield_pressure_;
    check.part = 1;
  }
  if (shaft_yield_pressure_ > 0.0 && peak / shaft_yield_pressure_ > check.utilisation) {
    check.utilisation = peak / shaft_yield_pressure_;
    check.part = 2;
  }
  return check;
}

double ElasticLaw::Normal(const ContactState& contact, double k,
                          Eigen::Vector2d* radial) const noexcept {
  *radial = -k * contact.penetration * contact.penetration_direction;
  return std::max(contact.normal_force, radial->norm());
}

void Ve1Law::PrepareLaw(const PartSpec& inner, const PartSpec& outer, const PressFitDimensions&) {
  clearance_ = 0.5 * (outer.size.nominal - inner.size.nominal);
  if (clearance_ < 0.0) clearance_ = 0.0;  // ideal geometry never interferes in VE1
}

double Ve1Law::Normal(const ContactState& contact, double k,
                      Eigen::Vector2d* radial) const noexcept {
  const double penetration = std::max(0.0, contact.offset_distance - clearance_);
  *radial = -k * penetration *
            Eigen::Vector2d(std::cos(contact.offset_angle), std::sin(contact.offset_angle));
  return radial->norm();
}

}  // namespace fitfeel::cylindrical
