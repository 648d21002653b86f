#pragma once

#include <string>
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

// Draws the gnuplot script `body` (one chart on the current terminal, reading its data files from
// `work`) at `width` x `height` pixels into every output file, as Render does: all formats
// rendered and checked before any file is installed.
FITFEEL_API void RenderScript(const std::string& body, int width, int height,
                              const std::vector<OutputFile>& outputs, const TempDir& work);

}  // namespace fitfeel::plot
