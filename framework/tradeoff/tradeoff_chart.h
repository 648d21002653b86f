#pragma once

#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/plot/gnuplot.h"
#include "framework/tradeoff/tradeoff_study.h"

namespace fitfeel::tradeoff {

// Which tick time the chart's x axis shows. The median is the usual cost; on a table-driven law it
// barely depends on the grid, while the 99th percentile (the ticks that threaten the 1 ms deadline)
// grows with it.
enum class TickCost { kP50, kP99 };

// The speed-accuracy chart, drawn by gnuplot (framework/plot's subprocess) into every output,
// all formats rendered before any is installed. Top panel: mean axial resistance +- the
// seed-to-seed standard deviation against the tick compute time (log x; median over the seeds of
// each run's p50 or p99), each point labelled with its grid, the reference's mean as a dashed line.
// Bottom panel: RMS error of the seed-averaged trace against the reference's and its sampling-noise
// floor (log y; the reference itself has no error and is left out). Throws UnsupportedError without
// gnuplot.
FITFEEL_API void RenderTradeoffChart(const std::vector<GridRow>& rows, const std::string& title,
                                     TickCost cost, const std::vector<plot::OutputFile>& outputs);

}  // namespace fitfeel::tradeoff
