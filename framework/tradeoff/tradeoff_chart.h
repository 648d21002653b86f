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
// all formats rendered before any is installed. Accuracy is the RMS error of the seed-averaged
// axial trace against the reference's (log y; filled), with its sampling-noise floor (open); top
// panel against the prepare time, bottom panel against the tick compute time (median over the
// seeds of each run's p50 or p99). Each grid has its own colour and point type, named in the key,
// so no label sits beside a point. The reference itself has no error and is left out. Throws
// UnsupportedError without gnuplot.
FITFEEL_API void RenderTradeoffChart(const std::vector<GridRow>& rows, const std::string& title,
                                     TickCost cost, const std::vector<plot::OutputFile>& outputs);

}  // namespace fitfeel::tradeoff
