#pragma once

#include <string_view>

#include "framework/core/export.h"
#include "framework/iso286/iso286.h"

namespace fitfeel::iso286 {

// ISO 286-1 fit classes. Clearance: the hole's lower limit is at or above the shaft's upper limit
// (zero clearance included, as in H7/h6). Interference: the hole's upper limit is at or below the
// shaft's lower limit. Transition: anything between.
enum class FitClass { kClearance, kTransition, kInterference };

FITFEEL_API std::string_view ToString(FitClass fit_class);

// A hole and a shaft of the same nominal size mated. Clearance = hole size - shaft size; negative
// values are interference. In metres.
struct Fit {
  Limits hole;
  Limits shaft;
  double min_clearance = 0.0;  // EI - es
  double max_clearance = 0.0;  // ES - ei
  FitClass fit_class = FitClass::kClearance;
};

// Mates limits found by Lookup. Throws std::invalid_argument unless `hole` is a hole and `shaft` a
// shaft of the same nominal size.
FITFEEL_API Fit MakeFit(const Limits& hole, const Limits& shaft);

// "H7/g6" at a nominal size: the hole class (upper-case letter) before the slash, the shaft class
// after it. Throws std::invalid_argument as Lookup does, or for a malformed fit code.
FITFEEL_API Fit LookupFit(double nominal_m, std::string_view fit_code);

}  // namespace fitfeel::iso286
