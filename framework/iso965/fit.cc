#include "framework/iso965/fit.h"

#include <cmath>
#include <numbers>
#include <string>

#include "framework/core/error.h"

namespace fitfeel::iso965 {

ThreadFit MakeFit(const ThreadLimits& nut, const ThreadLimits& bolt) {
  if (!nut.designation.internal) {
    throw UserError(
        "the first class of a thread fit must be an internal thread's (position G or H, e.g. "
        "6H), found '" +
        nut.designation.tolerance_class + "'");
  }
  if (bolt.designation.internal) {
    throw UserError(
        "the second class of a thread fit must be an external thread's (position e, f, g or h, "
        "e.g. 6g), found '" +
        bolt.designation.tolerance_class + "'");
  }
  if (nut.designation.size.text != bolt.designation.size.text) {
    throw UserError("a thread fit needs one size for nut and bolt, found " +
                    nut.designation.size.text + " and " + bolt.designation.size.text);
  }
  ThreadFit fit;
  fit.nut = nut;
  fit.bolt = bolt;
  fit.min_clearance = nut.pitch_diameter.min() - bolt.pitch_diameter.max();
  fit.max_clearance = nut.pitch_diameter.max() - bolt.pitch_diameter.min();
  fit.flank_angle = std::numbers::pi / 3.0;
  const double per_clearance = std::tan(fit.flank_angle / 2.0);
  fit.min_axial_play = fit.min_clearance * per_clearance;
  fit.max_axial_play = fit.max_clearance * per_clearance;
  const double per_play = 2.0 * std::numbers::pi / bolt.designation.size.pitch;
  fit.min_angular_backlash = fit.min_axial_play * per_play;
  fit.max_angular_backlash = fit.max_axial_play * per_play;
  return fit;
}

ThreadFit LookupFit(std::string_view size, std::string_view fit_code) {
  const std::size_t slash = fit_code.find('/');
  if (slash == std::string_view::npos || fit_code.find('/', slash + 1) != std::string_view::npos) {
    throw UserError("a thread fit is written NUT/bolt (e.g. 6H/6g), found '" +
                    std::string(fit_code) + "'");
  }
  const std::string thread(size);
  // Nut first, so that an error names the nut when both are wrong.
  const ThreadLimits nut =
      Lookup(ParseDesignation(thread + " " + std::string(fit_code.substr(0, slash))));
  const ThreadLimits bolt =
      Lookup(ParseDesignation(thread + " " + std::string(fit_code.substr(slash + 1))));
  return MakeFit(nut, bolt);
}

}  // namespace fitfeel::iso965
