#include "framework/iso286/fit.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fitfeel::iso286 {

std::string_view ToString(FitClass fit_class) {
  switch (fit_class) {
    case FitClass::kClearance:
      return "clearance";
    case FitClass::kTransition:
      return "transition";
    case FitClass::kInterference:
      return "interference";
  }
  return "unknown";
}

Fit MakeFit(const Limits& hole, const Limits& shaft) {
  if (!hole.is_hole) {
    throw std::invalid_argument(
        "the first class of a fit must be a hole (upper-case letter, e.g. "
        "H7), found '" +
        hole.code + "'");
  }
  if (shaft.is_hole) {
    throw std::invalid_argument(
        "the second class of a fit must be a shaft (lower-case letter, "
        "e.g. g6), found '" +
        shaft.code + "'");
  }
  if (hole.nominal != shaft.nominal) {
    throw std::invalid_argument("a fit needs one nominal size for hole and shaft");
  }
  Fit fit;
  fit.hole = hole;
  fit.shaft = shaft;
  fit.min_clearance = hole.lower_deviation - shaft.upper_deviation;
  fit.max_clearance = hole.upper_deviation - shaft.lower_deviation;
  // Deviations are multiples of 0.05 um converted to metres; a difference below a picometre is a
  // rounding remainder of an exact zero (H7/h6), which the standard counts as clearance.
  constexpr double kZero = 1e-12;
  if (std::abs(fit.min_clearance) < kZero) fit.min_clearance = 0.0;
  if (std::abs(fit.max_clearance) < kZero) fit.max_clearance = 0.0;
  if (fit.min_clearance >= 0.0) {
    fit.fit_class = FitClass::kClearance;
  } else if (fit.max_clearance <= 0.0) {
    fit.fit_class = FitClass::kInterference;
  } else {
    fit.fit_class = FitClass::kTransition;
  }
  return fit;
}

Fit LookupFit(double nominal_m, std::string_view fit_code) {
  const std::size_t slash = fit_code.find('/');
  if (slash == std::string_view::npos || fit_code.find('/', slash + 1) != std::string_view::npos) {
    throw std::invalid_argument("an ISO 286 fit is written HOLE/shaft (e.g. H7/g6), found '" +
                                std::string(fit_code) + "'");
  }
  // Hole first, so that an error names the hole when both are wrong.
  const Limits hole = Lookup(nominal_m, fit_code.substr(0, slash));
  const Limits shaft = Lookup(nominal_m, fit_code.substr(slash + 1));
  return MakeFit(hole, shaft);
}

}  // namespace fitfeel::iso286
