#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "framework/core/config_node.h"
#include "framework/model/measured_surface.h"

namespace fitfeel::scenario {

// Physical bounds of a measurement's samples (docs/measured-parts.md): coordinates within 10 m
// (the bounds of a recording), and a radius within 1 mm of the nominal one: a fit's size and
// form deviations are micrometres, so a larger one is a wrong unit or frame, not a part.
inline constexpr double kMaxMeasuredCoordinate = 10.0;
inline constexpr double kMaxMeasuredDeviation = 1e-3;
// A dense CMM scan of a fit's surface is millions of points, tens of MB; a larger file is not a
// measurement of one part.
inline constexpr std::uintmax_t kMaxMeasurementBytes = std::uintmax_t{512} << 20;
// The file is read line by line and its samples kept (28 B each), so memory is bounded by these,
// not by the file's size: at most as many samples as the finest grid a part gets has cells
// (model.resolution: 4e6 cells, about 120 MB of samples), and lines of at most 64 KiB (a sample's
// line is tens of bytes; a longer one is not this format). Refused at the line that exceeds them.
inline constexpr std::size_t kMaxMeasurementSamples = 4'000'000;
inline constexpr std::size_t kMaxMeasurementLineBytes = std::size_t{64} << 10;

// Reads the CSV measurement `file` of the kind named by the scenario key `key`
// (parts.<part>.measured.<kind>): '#' comment lines, a header of `name [unit]` cells, then one
// sample per line. Roundness and straightness files have the columns height, angle and radius or
// deviation (any order); point clouds x, y, z (y along the mating axis, the part's mating frame).
// Throws ScenarioError at the key when the file cannot be read, and at file:line:column with the
// key path for a bad header, a cell that is not a finite number, a value outside physical sense
// (`nominal_radius` bounds the radius), a repeated sample, too few samples in a trace, a line
// longer than kMaxMeasurementLineBytes or more than kMaxMeasurementSamples samples. A found text
// is quoted with its control bytes escaped and cut to a few dozen characters ("...").
FITFEEL_API MeasuredSurface ReadMeasurement(const std::filesystem::path& file,
                                            MeasurementKind kind, double nominal_radius,
                                            const ConfigNode& key);

}  // namespace fitfeel::scenario
