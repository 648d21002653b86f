#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "framework/core/export.h"
#include "framework/plot/figure.h"
#include "framework/study/study_record.h"

namespace fitfeel::plot {

// A constant a chart compares against (e.g. the paper's VE1 method, which gives one force for
// every part pair).
struct ReferenceLine {
  std::string label;
  double value = 0.0;  // N
};

// The distribution of insertion force over the pairs of each study, as quantile curves (force
// against the fraction of pairs at or below it: a CDF with its axes swapped, so the force axis
// can be logarithmic when the pairs span decades). Two panels: each pair's mean and its maximum
// axial resistance. Throws UserError for no studies.
FITFEEL_API LineChart MakeStudyChart(const std::vector<study::StudyRecord>& studies,
                                     const std::optional<ReferenceLine>& reference);

// DIR/study.png from DIR's pairs.csv and study.json: the chart `fitfeel study` draws after its
// data files (and `fitfeel plot study DIR` draws again), for every writer of a study to share.
// Throws UserError for an unreadable study, UnsupportedError without gnuplot.
FITFEEL_API void WriteStudyChart(const std::filesystem::path& dir);

}  // namespace fitfeel::plot
