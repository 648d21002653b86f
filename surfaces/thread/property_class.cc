#include "surfaces/thread/property_class.h"

#include <array>
#include <string>

#include "framework/core/error.h"
#include "surfaces/thread/bolting_arguments.h"

namespace fitfeel::thread {
namespace {

constexpr double kMPa = 1e6;

// ISO 898-1 Table 3: R_m nominal; R_m min and R_eL / R_p0.2 min for d <= 16 mm and d > 16 mm.
constexpr std::array kClasses = {
    BoltPropertyClass("4.6", 400 * kMPa, 400 * kMPa, 240 * kMPa, 400 * kMPa, 240 * kMPa),
    BoltPropertyClass("5.6", 500 * kMPa, 500 * kMPa, 300 * kMPa, 500 * kMPa, 300 * kMPa),
    BoltPropertyClass("8.8", 800 * kMPa, 800 * kMPa, 640 * kMPa, 830 * kMPa, 660 * kMPa),
    BoltPropertyClass("10.9", 1000 * kMPa, 1040 * kMPa, 940 * kMPa, 1040 * kMPa, 940 * kMPa),
    BoltPropertyClass("12.9", 1200 * kMPa, 1220 * kMPa, 1100 * kMPa, 1220 * kMPa, 1100 * kMPa),
};

// ISO 898-1 draws the 8.8 boundary at d = 16 mm inclusive.
constexpr double kLargeAbove = 16e-3 + 1e-9;

}  // namespace

const BoltPropertyClass& BoltPropertyClass::Parse(std::string_view name) {
  std::string valid;
  for (const BoltPropertyClass& c : kClasses) {
    if (c.name() == name) return c;
    valid += (valid.empty() ? "" : ", ") + std::string(c.name());
  }
  throw UserError("BoltPropertyClass: unknown property class '" + std::string(name) +
                  "'; ISO 898-1 classes held: " + valid);
}

std::span<const BoltPropertyClass> BoltPropertyClass::All() { return kClasses; }

double BoltPropertyClass::min_tensile_strength(double nominal_diameter) const {
  RequirePositive("BoltPropertyClass::min_tensile_strength", "nominal_diameter", nominal_diameter,
                  Dimension::kLength);
  return nominal_diameter > kLargeAbove ? tensile_min_large_ : tensile_min_;
}

double BoltPropertyClass::min_yield_strength(double nominal_diameter) const {
  RequirePositive("BoltPropertyClass::min_yield_strength", "nominal_diameter", nominal_diameter,
                  Dimension::kLength);
  return nominal_diameter > kLargeAbove ? yield_min_large_ : yield_min_;
}

}  // namespace fitfeel::thread
