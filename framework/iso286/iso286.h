#pragma once

#include <string>
#include <string_view>

#include "framework/core/export.h"

namespace fitfeel::iso286 {

// Limits of one tolerance class (e.g. "H7", "g6", "js6") at a nominal size, from the tables of
// ISO 286-1/-2 carried as data. Deviations in metres, relative to the nominal size.
struct Limits {
  double nominal = 0.0;
  double lower_deviation = 0.0;  // ei (shaft) / EI (hole)
  double upper_deviation = 0.0;  // es (shaft) / ES (hole)
  double it = 0.0;               // standard tolerance value of the grade
  bool is_hole = false;          // upper-case letter
  std::string code;              // as given, normalised ("H7")
  double step_lower = 0.0;       // main size step (ISO 286-1 Table 1) holding the nominal, in m:
  double step_upper = 0.0;       // step_lower < nominal <= step_upper
};

// Throws std::invalid_argument with a clear message for an unknown letter or grade, a
// combination the standard does not define, or a nominal size outside the tables (0, 500 mm].
// A nominal size on a step boundary belongs to the lower step (30 mm is in 18-30 mm).
FITFEEL_API Limits Lookup(double nominal_m, std::string_view code);

}  // namespace fitfeel::iso286
