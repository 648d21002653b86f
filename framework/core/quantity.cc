#include "framework/core/quantity.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <system_error>

#include "framework/core/quantity_parse.h"

namespace fitfeel {
namespace {

// A unit converts to SI as mantissa * 10^exponent10 * factor. Decimal prefixes are applied to the
// decimal exponent of the text before it is converted to binary, so "8 um" becomes the double
// nearest to 8e-6 exactly as if the user had written "8e-6 m"; only units that are not a power of
// ten (degrees) need a floating-point factor.
struct Unit {
  std::string_view symbol;
  Dimension dimension;
  int exponent10;
  double factor;
  bool listed;  // shown in DescribeDimension (aliases such as "µm" are accepted, not listed)
  // Used by FormatQuantity. Machining states sizes in mm and tolerances and roughness in um (Ra
  // 0.4 um, not 400 nm), so nm is accepted but never chosen.
  bool formatted;
};

constexpr double kDeg = std::numbers::pi / 180.0;

constexpr std::array kUnits = {
    Unit{"nm", Dimension::kLength, -9, 1.0, true, false},
    Unit{"um", Dimension::kLength, -6, 1.0, true, true},
    Unit{"\u00b5m", Dimension::kLength, -6, 1.0, false, false},  // micro sign
    Unit{"\u03bcm", Dimension::kLength, -6, 1.0, false, false},  // Greek mu
    Unit{"mm", Dimension::kLength, -3, 1.0, true, true},
    Unit{"cm", Dimension::kLength, -2, 1.0, true, false},
    Unit{"m", Dimension::kLength, 0, 1.0, true, true},
    Unit{"mN", Dimension::kForce, -3, 1.0, true, true},
    Unit{"N", Dimension::kForce, 0, 1.0, true, true},
    Unit{"kN", Dimension::kForce, 3, 1.0, true, true},
    Unit{"Pa", Dimension::kPressure, 0, 1.0, true, true},
    Unit{"kPa", Dimension::kPressure, 3, 1.0, true, true},
    Unit{"MPa", Dimension::kPressure, 6, 1.0, true, true},
    Unit{"GPa", Dimension::kPressure, 9, 1.0, true, true},
    Unit{"us", Dimension::kTime, -6, 1.0, true, true},
    Unit{"\u00b5s", Dimension::kTime, -6, 1.0, false, false},
    Unit{"\u03bcs", Dimension::kTime, -6, 1.0, false, false},
    Unit{"ms", Dimension::kTime, -3, 1.0, true, true},
    Unit{"s", Dimension::kTime, 0, 1.0, true, true},
    Unit{"Hz", Dimension::kFrequency, 0, 1.0, true, true},
    Unit{"kHz", Dimension::kFrequency, 3, 1.0, true, true},
    Unit{"mm/s", Dimension::kVelocity, -3, 1.0, true, true},
    Unit{"m/s", Dimension::kVelocity, 0, 1.0, true, true},
    Unit{"N/m", Dimension::kStiffness, 0, 1.0, true, true},
    Unit{"N/mm", Dimension::kStiffness, 3, 1.0, true, true},
    Unit{"N/um", Dimension::kStiffness, 6, 1.0, true, true},
    Unit{"kN/mm", Dimension::kStiffness, 6, 1.0, true, false},
    Unit{"N*s/m", Dimension::kDamping, 0, 1.0, true, true},
    Unit{"Ns/m", Dimension::kDamping, 0, 1.0, true, false},
    Unit{"g", Dimension::kMass, -3, 1.0, true, true},
    Unit{"kg", Dimension::kMass, 0, 1.0, true, true},
    Unit{"rad", Dimension::kAngle, 0, 1.0, true, false},
    Unit{"mrad", Dimension::kAngle, -3, 1.0, true, false},
    Unit{"deg", Dimension::kAngle, 0, kDeg, true, true},
    Unit{"rad/s", Dimension::kAngularVelocity, 0, 1.0, true, false},
    Unit{"deg/s", Dimension::kAngularVelocity, 0, kDeg, true, true},
    Unit{"N*mm", Dimension::kTorque, -3, 1.0, true, true},
    Unit{"N*m", Dimension::kTorque, 0, 1.0, true, true},
    Unit{"Nm", Dimension::kTorque, 0, 1.0, true, false},
    Unit{"N*m/rad", Dimension::kAngularStiffness, 0, 1.0, true, true},
    Unit{"J", Dimension::kEnergy, 0, 1.0, true, true},
};

const Unit* FindUnit(std::string_view symbol) {
  for (const Unit& unit : kUnits) {
    if (unit.symbol == symbol) return &unit;
  }
  return nullptr;
}

// Name of the physical quantity without article, for "kg is a unit of mass".
std::string_view BareName(Dimension dimension) {
  switch (dimension) {
    case Dimension::kDimensionless:
      return "dimensionless number";
    case Dimension::kLength:
      return "length";
    case Dimension::kForce:
      return "force";
    case Dimension::kPressure:
      return "pressure";
    case Dimension::kTime:
      return "time";
    case Dimension::kFrequency:
      return "frequency";
    case Dimension::kVelocity:
      return "velocity";
    case Dimension::kStiffness:
      return "stiffness";
    case Dimension::kDamping:
      return "damping";
    case Dimension::kMass:
      return "mass";
    case Dimension::kAngle:
      return "angle";
    case Dimension::kAngularVelocity:
      return "angular velocity";
    case Dimension::kTorque:
      return "torque";
    case Dimension::kAngularStiffness:
      return "angular stiffness";
    case Dimension::kEnergy:
      return "energy";
  }
  return "unknown quantity";
}

bool IsSpace(char c) { return c == ' ' || c == '\t'; }
bool IsDigit(char c) { return c >= '0' && c <= '9'; }

std::string_view Trim(std::string_view text) {
  while (!text.empty() && IsSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && IsSpace(text.back())) text.remove_suffix(1);
  return text;
}

std::string Quote(std::string_view text) { return "'" + std::string(text) + "'"; }

bool IsNonFiniteWord(std::string_view word) {
  if (!word.empty() && (word.front() == '+' || word.front() == '-')) word.remove_prefix(1);
  if (!word.empty() && word.front() == '.') word.remove_prefix(1);  // YAML spells them .inf/.nan
  std::string lower;
  for (char c : word) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return lower == "inf" || lower == "infinity" || lower == "nan";
}

// The decimal number at the start of `text`: [+-] digits [. digits] [(e|E) [+-] digits], at least
// one digit in the mantissa. Returns its length (0 if there is none) and splits it into the
// mantissa text and the decimal exponent.
struct DecimalNumber {
  std::size_t length = 0;
  std::string mantissa;
  long long exponent = 0;
  bool exponent_overflow = false;
};

DecimalNumber ScanNumber(std::string_view text) {
  DecimalNumber out;
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < text.size() && IsDigit(text[i])) ++i, ++digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && IsDigit(text[i])) ++i, ++digits;
  }
  if (digits == 0) return out;
  const std::size_t mantissa_end = i;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
    const std::size_t exponent_digits_start = j;
    while (j < text.size() && IsDigit(text[j])) ++j;
    if (j > exponent_digits_start) {
      std::string_view exponent_text = text.substr(i + 1, j - i - 1);
      if (exponent_text.front() == '+') exponent_text.remove_prefix(1);
      const auto result = std::from_chars(
          exponent_text.data(), exponent_text.data() + exponent_text.size(), out.exponent);
      if (result.ec != std::errc{}) out.exponent_overflow = true;
      i = j;
    }
  }
  out.length = i;
  out.mantissa = std::string(text.substr(0, mantissa_end));
  if (out.mantissa.front() == '+') out.mantissa.erase(0, 1);
  return out;
}

}  // namespace

namespace internal {

std::string DimensionName(Dimension dimension) {
  const std::string_view name = BareName(dimension);
  const bool vowel = name.front() == 'a' || name.front() == 'e';
  return std::string(vowel ? "an " : "a ") + std::string(name);
}

QuantityParse TryParseQuantity(std::string_view raw, Dimension dimension) {
  QuantityParse out;
  const std::string_view text = Trim(raw);
  if (text.empty()) {
    out.problem = "an empty value";
    return out;
  }
  const DecimalNumber number = ScanNumber(text);
  if (number.length == 0) {
    const std::size_t end = text.find_first_of(" \t");
    const bool non_finite = IsNonFiniteWord(text.substr(0, end));
    out.problem = Quote(text) + (non_finite ? " (not a finite number)" : " (not a number)");
    return out;
  }
  const std::string_view rest = Trim(text.substr(number.length));
  const std::size_t space = rest.find_first_of(" \t");
  const std::string_view unit_text = rest.substr(0, space);
  const std::string_view trailing =
      space == std::string_view::npos ? std::string_view{} : Trim(rest.substr(space));

  const Unit* unit = nullptr;
  if (dimension == Dimension::kDimensionless) {
    if (!unit_text.empty()) {
      const Unit* found = FindUnit(unit_text);
      out.problem =
          Quote(text) + (found != nullptr
                             ? " (" + std::string(unit_text) + " is a unit of " +
                                   std::string(BareName(found->dimension)) +
                                   "; a dimensionless number has no unit)"
                             : " (unexpected '" + std::string(rest) + "' after the number)");
      return out;
    }
  } else {
    if (unit_text.empty()) {
      out.problem = Quote(text) + " (no unit)";
      return out;
    }
    unit = FindUnit(unit_text);
    if (unit == nullptr) {
      out.problem = Quote(text) + " (unknown unit '" + std::string(unit_text) + "')";
      return out;
    }
    if (unit->dimension != dimension) {
      out.problem = Quote(text) + " (" + std::string(unit_text) + " is a unit of " +
                    std::string(BareName(unit->dimension)) + ")";
      return out;
    }
    if (!trailing.empty()) {
      out.problem = Quote(text) + " (unexpected '" + std::string(trailing) + "' after the unit)";
      return out;
    }
  }

  // Exponents beyond a few hundred are out of range of a double either way; clamping keeps the
  // arithmetic below from overflowing while still producing an out-of-range result.
  constexpr long long kClamp = 100000;
  long long exponent = number.exponent;
  if (number.exponent_overflow) exponent = number.exponent < 0 ? -kClamp : kClamp;
  exponent = std::max(-kClamp, std::min(kClamp, exponent)) + (unit ? unit->exponent10 : 0);
  const std::string decimal = number.mantissa + "e" + std::to_string(exponent);
  double value = 0.0;
  const auto result = std::from_chars(decimal.data(), decimal.data() + decimal.size(), value);
  if (result.ec != std::errc{} || result.ptr != decimal.data() + decimal.size()) {
    // libstdc++ reports both overflow and underflow as out of range. A value whose magnitude is
    // below the smallest double is not a meaningful scenario value either.
    out.problem = Quote(text) + " (not a finite number: magnitude out of the range of a double)";
    return out;
  }
  if (unit != nullptr && unit->factor != 1.0) value *= unit->factor;
  if (!std::isfinite(value)) {
    out.problem = Quote(text) + " (not a finite number)";
    return out;
  }
  out.value = value;
  return out;
}

}  // namespace internal

std::string DescribeDimension(Dimension dimension) {
  std::string out = internal::DimensionName(dimension);
  if (dimension == Dimension::kDimensionless) return out + " (no unit, e.g. 0.15)";
  std::string units;
  for (const Unit& unit : kUnits) {
    if (unit.dimension == dimension && unit.listed) {
      units += (units.empty() ? "" : ", ") + std::string(unit.symbol);
    }
  }
  return out + " (" + units + ")";
}

double ParseQuantity(std::string_view text, Dimension dimension) {
  internal::QuantityParse parsed = internal::TryParseQuantity(text, dimension);
  if (!parsed.problem.empty()) {
    throw std::invalid_argument("expected " + DescribeDimension(dimension) + ", found " +
                                parsed.problem);
  }
  return parsed.value;
}

std::string FormatQuantity(double si_value, Dimension dimension) {
  // Ten significant digits: enough that parsing the text back gives the value to 1e-10 relative,
  // few enough that binary noise of the scaling (2e-5 / 1e-6) does not show.
  auto number = [](double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.10g", v);
    return std::string(buffer);
  };
  if (dimension == Dimension::kDimensionless) return number(si_value);
  const Unit* chosen = nullptr;
  const double magnitude = std::fabs(si_value);
  for (const Unit& unit : kUnits) {
    if (unit.dimension != dimension || !unit.formatted) continue;
    const double scale = std::pow(10.0, unit.exponent10) * unit.factor;
    if (chosen == nullptr) chosen = &unit;  // the smallest unit, for magnitudes below it
    if (magnitude == 0.0 || !std::isfinite(magnitude)) {
      if (unit.exponent10 == 0 && unit.factor == 1.0) chosen = &unit;
    } else if (scale <= magnitude * (1.0 + 1e-12)) {
      chosen = &unit;
    }
  }
  if (chosen == nullptr) return number(si_value);
  const double scale = std::pow(10.0, chosen->exponent10) * chosen->factor;
  return number(si_value / scale) + " " + std::string(chosen->symbol);
}

std::optional<long> ParseInteger(std::string_view text, long min, long max) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || (text.front() == '-' && min >= 0)) return std::nullopt;
  long value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return std::nullopt;
  if (value < min || value > max) return std::nullopt;
  return value;
}

std::optional<std::uint64_t> ParseSeed(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.front() < '0' || text.front() > '9') return std::nullopt;
  std::uint64_t value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

std::string DescribeIntegerRange(long min, long max) {
  constexpr long kLow = std::numeric_limits<long>::min(), kHigh = std::numeric_limits<long>::max();
  if (min != kLow && max != kHigh) {
    return "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  }
  if (min != kLow) return "an integer >= " + std::to_string(min);
  if (max != kHigh) return "an integer <= " + std::to_string(max);
  return "an integer";
}

}  // namespace fitfeel
