#pragma once

#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/plot/gnuplot.h"
#include "framework/tradeoff/tradeoff_study.h"

namespace fitfeel::tradeoff {

// The speed-accuracy chart, drawn by gnuplot (framework/plot's subprocess) into every output,
// all formats rendered before any is installed. Top panel: mean axial resistance +- the
// seed-to-seed standard deviation against the median tick compute time (log x), each point
// labelled with its grid, the reference's mean as a dashed line. Bottom panel: RMS error of the
// seed-averaged trace against the reference's and its sampling-noise floor (log y; the
// reference itself has no error and is left out). Throws UnsupportedError without gnuplot.
FITFEEL_API void RenderTradeoffChart(const std::vector<GridRow>& rows, const std::string& title,
                                     const std::vector<plot::OutputFile>& outputs);

}  // namespace fitfeel::tradeoff
