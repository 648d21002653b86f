#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "framework/core/export.h"
#include "framework/model/discretizer.h"

namespace fitfeel::tradeoff {

// The grids a trade-off study runs, rows x columns per part (auto: the surface type's choice).
// Default: 8x36 to 160x1440, each step refining one direction or both (the finest is the
// reference), so the chart spans from a grid far below the scenario's 40x360 to one 16 times
// finer in cells.
FITFEEL_API std::vector<Resolution> DefaultLadder();

// Parses "8x36,20x90,auto": comma-separated ROWSxCOLUMNS (positive integers, columns even, at
// most kMaxCellsPerPart cells) or `auto`. Throws UserError naming the bad item; duplicates are an
// error too (they would only repeat a run).
FITFEEL_API std::vector<Resolution> ParseLadder(std::string_view text);

// "40x360", or "auto".
FITFEEL_API std::string Label(const Resolution& resolution);

// A bound that keeps a typo (4000x36000) from asking for gigabytes: 4 million cells per part,
// 17 times the default ladder's finest grid.
inline constexpr long kMaxCellsPerPart = 4'000'000;

}  // namespace fitfeel::tradeoff
