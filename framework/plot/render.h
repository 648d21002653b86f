#pragma once

#include <vector>

#include "framework/core/export.h"
#include "framework/plot/figure.h"
#include "framework/plot/gnuplot.h"

namespace fitfeel::plot {

// Draws a chart with gnuplot into every output file (PNG through pngcairo, SVG through svg), all
// formats rendered before any file is installed. Throws UnsupportedError when gnuplot is absent,
// std::invalid_argument for malformed chart data (a bug of the caller).
FITFEEL_API void Render(const LineChart& chart, const std::vector<OutputFile>& outputs);
FITFEEL_API void Render(const HeatMapChart& chart, const std::vector<OutputFile>& outputs);

}  // namespace fitfeel::plot
