#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "framework/core/export.h"

namespace fitfeel {

// Physical dimension of a scenario quantity. Files carry units ("20 mm", "210 GPa"); inside, every
// value is SI (m, N, Pa, s, kg, rad).
enum class Dimension {
  kDimensionless,     // "0.15" (friction coefficient, Poisson's ratio, ratios)
  kLength,            // m: nm, um, mm, cm, m
  kForce,             // N: mN, N, kN
  kPressure,          // Pa: Pa, kPa, MPa, GPa
  kTime,              // s: us, ms, s
  kFrequency,         // Hz: Hz, kHz
  kVelocity,          // m/s: mm/s, m/s
  kStiffness,         // N/m: N/m, N/mm, N/um, kN/mm
  kDamping,           // N*s/m: N*s/m, Ns/m
  kMass,              // kg: g, kg
  kAngle,             // rad: rad, mrad, deg
  kAngularVelocity,   // rad/s: rad/s, deg/s
  kTorque,            // N*m: N*m, Nm, N*mm
  kAngularStiffness,  // N*m/rad
  kEnergy,            // J
};

// Human-readable name and the units accepted for it, e.g. "a length (nm, um, mm, cm, m)".
FITFEEL_API std::string DescribeDimension(Dimension dimension);

// Parses "<number> <unit>" (a space between them is optional) into SI. A dimensionless quantity is
// a bare number. Throws std::invalid_argument with a message naming the accepted units when the
// text is not a number, the unit is missing, unknown or of another dimension, or the value is not
// finite.
FITFEEL_API double ParseQuantity(std::string_view text, Dimension dimension);

// Integers as scenario keys and command-line options both take them: an optional '+', decimal
// digits, nothing else, within [min, max]. Empty on anything else (empty text, a sign where none
// belongs, an overflow, a fraction): never clamped.
FITFEEL_API std::optional<long> ParseInteger(std::string_view text, long min, long max);
// "an integer", "an integer >= 0", "an integer in [1, 1000]": what ParseInteger accepts.
FITFEEL_API std::string DescribeIntegerRange(long min, long max);
// A random generator's seed, as run.seed and every --seed take it: ParseInteger's form over the
// whole 64-bit range, so that each seed a fit study gives its pairs (pairs.csv) runs again.
FITFEEL_API std::optional<std::uint64_t> ParseSeed(std::string_view text);
inline constexpr const char* kSeedRange = "an integer in [0, 18446744073709551615]";

// Formats an SI value in a unit suited to its magnitude, e.g. 2.0e-5 m -> "20 um".
FITFEEL_API std::string FormatQuantity(double value_si, Dimension dimension);

}  // namespace fitfeel
