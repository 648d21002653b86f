#include "surfaces/thread/bolted_joint.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "framework/core/error.h"
#include "surfaces/thread/bolting_arguments.h"

namespace fitfeel::thread {
namespace {

void CheckThread(const char* function, double nominal_diameter, double pitch) {
  RequirePositive(function, "nominal_diameter", nominal_diameter, Dimension::kLength);
  RequirePositive(function, "pitch", pitch, Dimension::kLength);
  // Beyond d/3 the minor diameter of a 60 deg thread shrinks below 0.6 d: no standard thread.
  RequireWithin(function, "pitch", pitch, 0.0, nominal_diameter / 3.0, Dimension::kLength);
}

double CircleArea(double diameter) { return 0.25 * std::numbers::pi * diameter * diameter; }

void CheckClampedParts(const char* function, const ClampedParts& parts) {
  RequirePositive(function, "bearing_diameter", parts.bearing_diameter, Dimension::kLength);
  RequirePositive(function, "hole_diameter", parts.hole_diameter, Dimension::kLength);
  RequirePositive(function, "clamp_length", parts.clamp_length, Dimension::kLength);
  RequirePositive(function, "outer_diameter", parts.outer_diameter, Dimension::kLength);
  RequirePositive(function, "modulus", parts.modulus, Dimension::kPressure);
  RequireLess(function, "hole_diameter", parts.hole_diameter, "bearing_diameter",
              parts.bearing_diameter, Dimension::kLength);
  RequireLess(function, "hole_diameter", parts.hole_diameter, "outer_diameter",
              parts.outer_diameter, Dimension::kLength);
}

}  // namespace

double PitchDiameter(double nominal_diameter, double pitch) {
  CheckThread("PitchDiameter", nominal_diameter, pitch);
  return nominal_diameter - 0.649519 * pitch;
}

double MinorDiameter(double nominal_diameter, double pitch) {
  CheckThread("MinorDiameter", nominal_diameter, pitch);
  return nominal_diameter - 1.226869 * pitch;
}

double StressArea(double nominal_diameter, double pitch) {
  const double d0 =
      0.5 * (PitchDiameter(nominal_diameter, pitch) + MinorDiameter(nominal_diameter, pitch));
  return CircleArea(d0);
}

double StressSectionModulus(double nominal_diameter, double pitch) {
  const double d0 =
      0.5 * (PitchDiameter(nominal_diameter, pitch) + MinorDiameter(nominal_diameter, pitch));
  return std::numbers::pi * d0 * d0 * d0 / 16.0;
}

BoltResilience ThroughBoltResilience(const ThroughBolt& bolt) {
  constexpr const char* kFunction = "ThroughBoltResilience";
  CheckThread(kFunction, bolt.nominal_diameter, bolt.pitch);
  RequirePositive(kFunction, "clamp_length", bolt.clamp_length, Dimension::kLength);
  RequirePositive(kFunction, "bolt_modulus", bolt.bolt_modulus, Dimension::kPressure);
  RequirePositive(kFunction, "nut_modulus", bolt.nut_modulus, Dimension::kPressure);
  const double d = bolt.nominal_diameter;
  const double e_s = bolt.bolt_modulus;
  const double a_n = CircleArea(d);
  const double a_d3 = CircleArea(MinorDiameter(d, bolt.pitch));
  BoltResilience r{};
  double shank_length = 0.0;
  for (const CylindricalSection& section : bolt.shank) {
    RequirePositive(kFunction, "shank section length", section.length, Dimension::kLength);
    RequirePositive(kFunction, "shank section diameter", section.diameter, Dimension::kLength);
    // A section wider than the thread's nominal diameter would not pass the clearance hole.
    RequireWithin(kFunction, "shank section diameter", section.diameter, 0.0, d,
                  Dimension::kLength);
    shank_length += section.length;
    r.shank += section.length / (e_s * CircleArea(section.diameter));
  }
  // The sections lie inside the clamp; a rounding margin keeps l_K = sum l_i accepted.
  RequireWithin(kFunction, "total shank length", shank_length, 0.0,
                bolt.clamp_length * (1.0 + 1e-12), Dimension::kLength);
  const double free_thread = std::max(0.0, bolt.clamp_length - shank_length);
  // VDI 2230: the head's substitute length 0.5 d for hexagon heads, the engaged thread's 0.5 d,
  // the nut's 0.4 d for a through bolt.
  r.head = 0.5 * d / (e_s * a_n);
  r.free_thread = free_thread / (e_s * a_d3);
  r.engaged_thread = 0.5 * d / (e_s * a_d3);
  r.nut = 0.4 * d / (bolt.nut_modulus * a_n);
  return r;
}

double ThroughBoltConeTangent(double clamp_length, double bearing_diameter, double outer_diameter) {
  constexpr const char* kFunction = "ThroughBoltConeTangent";
  RequirePositive(kFunction, "clamp_length", clamp_length, Dimension::kLength);
  RequirePositive(kFunction, "bearing_diameter", bearing_diameter, Dimension::kLength);
  RequirePositive(kFunction, "outer_diameter", outer_diameter, Dimension::kLength);
  const double beta_l = clamp_length / bearing_diameter;
  const double y = outer_diameter / bearing_diameter;
  const double tangent = 0.362 + 0.032 * std::log(beta_l / 2.0) + 0.153 * std::log(y);
  // The fit leaves its range (and turns the cone inside out) for plates far thinner than the
  // bearing face is wide.
  if (!(tangent > 0.0)) {
    throw UserError(
        "ThroughBoltConeTangent: clamp_length " + FormatQuantity(clamp_length, Dimension::kLength) +
        " and outer_diameter " + FormatQuantity(outer_diameter, Dimension::kLength) +
        " against bearing_diameter " + FormatQuantity(bearing_diameter, Dimension::kLength) +
        " give tan phi <= 0, outside VDI 2230's cone fit");
  }
  return tangent;
}

PlateResilience ThroughBoltPlateResilience(const ClampedParts& parts) {
  CheckClampedParts("ThroughBoltPlateResilience", parts);
  return ThroughBoltPlateResilience(
      parts,
      ThroughBoltConeTangent(parts.clamp_length, parts.bearing_diameter, parts.outer_diameter));
}

PlateResilience ThroughBoltPlateResilience(const ClampedParts& parts, double cone_tangent) {
  constexpr const char* kFunction = "ThroughBoltPlateResilience";
  CheckClampedParts(kFunction, parts);
  RequirePositive(kFunction, "cone_tangent", cone_tangent, Dimension::kDimensionless);
  const double dw = parts.bearing_diameter, dh = parts.hole_diameter;
  const double lk = parts.clamp_length, da = parts.outer_diameter, e = parts.modulus;
  const double t = cone_tangent;
  PlateResilience r{0.0, t, dw + lk * t, DeformationBody::kCone};
  if (da <= dw) {
    r.body = DeformationBody::kSleeve;
    r.resilience = lk / (e * 0.25 * std::numbers::pi * (da * da - dh * dh));
  } else if (da < r.limit_diameter) {
    r.body = DeformationBody::kConeAndSleeve;
    const double cones =
        2.0 / (dh * t) * std::log(((dw + dh) * (da - dh)) / ((dw - dh) * (da + dh)));
    const double sleeve = 4.0 / (da * da - dh * dh) * (lk - (da - dw) / t);
    r.resilience = (cones + sleeve) / (e * std::numbers::pi);
  } else {
    const double top = r.limit_diameter;
    r.resilience = 2.0 * std::log(((dw + dh) * (top - dh)) / ((dw - dh) * (top + dh))) /
                   (e * std::numbers::pi * dh * t);
  }
  return r;
}

double PreloadPerTurn(double pitch, double bolt_resilience, double plate_resilience) {
  constexpr const char* kFunction = "PreloadPerTurn";
  RequirePositive(kFunction, "pitch", pitch, Dimension::kLength);
  RequirePositive(kFunction, "bolt_resilience", bolt_resilience, Dimension::kDimensionless);
  RequirePositive(kFunction, "plate_resilience", plate_resilience, Dimension::kDimensionless);
  return pitch / (bolt_resilience + plate_resilience);
}

AssemblyStress TighteningStress(double nominal_diameter, double pitch, double preload,
                                double thread_torque, double yield_strength) {
  constexpr const char* kFunction = "TighteningStress";
  CheckThread(kFunction, nominal_diameter, pitch);
  RequireNonNegative(kFunction, "preload", preload, Dimension::kForce);
  RequireNonNegative(kFunction, "thread_torque", thread_torque, Dimension::kTorque);
  RequirePositive(kFunction, "yield_strength", yield_strength, Dimension::kPressure);
  AssemblyStress s{};
  s.tensile = preload / StressArea(nominal_diameter, pitch);
  s.torsional = thread_torque / StressSectionModulus(nominal_diameter, pitch);
  s.equivalent = EquivalentStress(s.tensile, s.torsional);
  s.utilisation = s.equivalent / yield_strength;
  return s;
}

double PermissibleAssemblyPreload(double nominal_diameter, double pitch, double yield_strength,
                                  double thread_friction, double utilisation) {
  constexpr const char* kFunction = "PermissibleAssemblyPreload";
  CheckThread(kFunction, nominal_diameter, pitch);
  RequirePositive(kFunction, "yield_strength", yield_strength, Dimension::kPressure);
  RequireWithin(kFunction, "thread_friction", thread_friction, 0.0, 1.0, Dimension::kDimensionless);
  RequireWithin(kFunction, "utilisation", utilisation, 1e-6, 1.0, Dimension::kDimensionless);
  const double d2 = PitchDiameter(nominal_diameter, pitch);
  const double d0 = 0.5 * (d2 + MinorDiameter(nominal_diameter, pitch));
  const double bracket =
      1.5 * d2 / d0 * (pitch / (std::numbers::pi * d2) + 1.155 * thread_friction);
  return CircleArea(d0) * utilisation * yield_strength / std::sqrt(1.0 + 3.0 * bracket * bracket);
}

}  // namespace fitfeel::thread
