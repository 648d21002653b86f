#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/stability/wall_experiment.h"

namespace fitfeel {

// A stability map: every combination of method x rate x stiffness x damping, each run as a
// WallExperiment that otherwise copies `base` (device spec, force scale, hand, horizon).
struct StabilityMapSettings {
  WallExperiment base;
  std::vector<RenderingMethod> methods{RenderingMethod::kDirect, RenderingMethod::kCoupled};
  std::vector<double> rates;        // Hz
  std::vector<double> stiffnesses;  // N/m at the device
  std::vector<double> dampings;     // N*s/m at the device
};

struct StabilityMapRow {
  RenderingMethod method = RenderingMethod::kDirect;
  double rate = 0.0;
  double stiffness = 0.0;
  double damping = 0.0;
  WallOutcome outcome;
};

// Runs the sweep (methods outermost, then rates, dampings, stiffnesses). Throws UserError for an
// empty axis or a parameter RunWallExperiment refuses.
FITFEEL_API std::vector<StabilityMapRow> SweepStabilityMap(const StabilityMapSettings& settings);

// `count_per_decade` log-spaced values from `low` to `high` inclusive (both > 0).
FITFEEL_API std::vector<double> LogSpaced(double low, double high, int count_per_decade);

// The CSV text: a header line
//   method,rate_Hz,stiffness_N_per_m,damping_Ns_per_m,bound_ok,stable,energy_growth_J,peak_force_N
// then one line per row; bound_ok and stable are 1 or 0.
FITFEEL_API std::string StabilityMapCsv(const std::vector<StabilityMapRow>& rows);

// Writes `text` to `path` through a temporary file in the same folder renamed over it, so that a
// reader never sees half a map and a failure leaves any previous file alone. Throws UserError.
FITFEEL_API void WriteFileAtomically(const std::filesystem::path& path, const std::string& text);

}  // namespace fitfeel
