#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/plot/gnuplot.h"
#include "framework/safety/force_mapping.h"

namespace fitfeel::plot {

// One run of `fitfeel plot mapping`: where its scene force landed on the device.
struct MappingPoint {
  std::string label;      // the scene's name (summary.json's `scenario`), else the folder's
  double scene_N = 0.0;   // axial_resistance_N mean
  double device_N = 0.0;  // delivered_force_N mean
};

struct MappingChartData {
  ForceMapping mapping;  // the first run's
  std::string device;    // the first run's safety.device_model
  std::vector<MappingPoint> points;
  std::vector<std::string> notes;  // runs left out, and why
};

// The mapping summary.json's safety.force_mapping records. Throws UserError naming the file when
// it has none (a run of an older fitfeel) or a malformed one.
FITFEEL_API ForceMapping ReadForceMapping(const std::filesystem::path& summary_json);

// Reads each run folder's summary.json: the mapping of the first, a point for every run that
// reached the constrained stage. Throws UserError for no folder, a summary without a mapping, or a
// missing or malformed value.
FITFEEL_API MappingChartData LoadMappingRuns(const std::vector<std::filesystem::path>& dirs);

// The chart of `fitfeel plot mapping`: the mapping's device force against the scene force on a
// logarithmic axis from 0.01 N to twice the scene top, and each run as a labelled point. Runs
// at the same place (within 2 %) share one point and one label.
FITFEEL_API void RenderMappingChart(const MappingChartData& data,
                                    const std::vector<OutputFile>& outputs);

}  // namespace fitfeel::plot
