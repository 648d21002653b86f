#pragma once

#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/plot/gnuplot.h"
#include "framework/stability/stability_map.h"

namespace fitfeel {

// The stability map as a chart, drawn by gnuplot (framework/plot) into every output, all formats
// rendered before any is installed: one panel per virtual damping B, contact stiffness at the
// device (log x) against the rate (log y), direct rendering stable (filled) or unstable (open),
// coupled rendering stable or unstable drawn just above its rate so the two stay apart, and the
// passivity bound K = 2 (b - |B|) / T as a line. `device_damping` is b, N*s/m. Throws
// UnsupportedError without gnuplot, std::invalid_argument for no rows or no output.
FITFEEL_API void RenderStabilityMap(const std::vector<StabilityMapRow>& rows, double device_damping,
                                    const std::string& title,
                                    const std::vector<plot::OutputFile>& outputs);

}  // namespace fitfeel
