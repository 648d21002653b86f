#pragma once

#include <string_view>

#include "framework/core/export.h"
#include "framework/iso965/iso965.h"

namespace fitfeel::iso965 {

// A nut and a bolt of one ISO thread size mated. Lengths in metres, angles in radians.
struct ThreadFit {
  ThreadLimits nut;
  ThreadLimits bolt;
  double min_clearance = 0.0;  // D2 min - d2 max
  double max_clearance = 0.0;  // D2 max - d2 min
  double flank_angle = 0.0;    // alpha, 60 degrees (ISO 68-1)
  // Free axial travel of the bolt between its two flank contacts, clearance x tan(alpha/2)
  // (README.md derives it), and the turn that travel takes, 2 pi play / P.
  double min_axial_play = 0.0;
  double max_axial_play = 0.0;
  double min_angular_backlash = 0.0;
  double max_angular_backlash = 0.0;
};

// Throws UserError unless `nut` is an internal and `bolt` an external thread of one size.
FITFEEL_API ThreadFit MakeFit(const ThreadLimits& nut, const ThreadLimits& bolt);

// ("M10x1.5", "6H/6g"): the nut's class before the slash, the bolt's after it; either may give
// pitch and crest classes apart ("5H6H/4g6g"). Throws UserError as ParseDesignation and Lookup
// do, or for a malformed fit code.
FITFEEL_API ThreadFit LookupFit(std::string_view size, std::string_view fit_code);

}  // namespace fitfeel::iso965
