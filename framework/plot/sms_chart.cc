#include "framework/plot/sms_chart.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "framework/core/error.h"

namespace fitfeel::plot {

namespace {

constexpr double kMicrometre = 1e-6;
constexpr double kMillimetre = 1e-3;
constexpr double kDegree = std::numbers::pi / 180.0;

std::string Micrometres(double metres) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%+.2f µm", metres / kMicrometre);
  return buffer;
}

std::string SizeText(const PartSpec& part) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g mm", part.size.nominal / kMillimetre);
  std::string text = buffer;
  if (!part.size.iso_code.empty()) return text + " " + part.size.iso_code;
  return text + " (" + Micrometres(part.size.lower_deviation) + " / " +
         Micrometres(part.size.upper_deviation) + " on the diameter)";
}

// Angles in degrees on [0, 360): the map's vertical axis then reads as a compass around the axis.
Eigen::VectorXd Degrees(const Eigen::VectorXd& radians) { return radians / kDegree; }

}  // namespace

RadialLimits VariationLimits(const PartSpec& part) {
  return {0.5 * part.size.lower_deviation, 0.5 * part.size.upper_deviation};
}

RadialLimits ToleranceSpaceLimits(const PartSpec& inner, const PartSpec& outer) {
  const RadialLimits i = VariationLimits(inner), o = VariationLimits(outer);
  return {o.lower - i.upper, o.upper - i.lower};
}

HeatMap MakeSkinProfileMap(const PartSpec& part, const SkinModelShape& sms) {
  const SurfaceGrid& grid = sms.grid;
  if (grid.rows < 2 || grid.columns < 2 || sms.variation.size() != grid.size() ||
      grid.row_position.size() != grid.rows || grid.column_angle.size() != grid.columns) {
    throw UserError("the skin model shape of part '" + part.name + "' (" +
                    std::to_string(grid.rows) + " x " + std::to_string(grid.columns) +
                    " cells) cannot be drawn: a map needs at least 2 x 2 cells and one variation "
                    "per cell");
  }
  const bool inner = part.role == Role::kInner;
  const RadialLimits limits = VariationLimits(part);
  HeatMap map;
  map.title = part.name + " (" + (inner ? "inner" : "outer") + ", " + SizeText(part) +
              "): skin profile variation V";
  map.x_label = "axial position (mm)";
  map.y_label = "direction angle (°)";
  map.colour_label = "V (µm)";
  map.x = grid.row_position / kMillimetre;
  map.y = Degrees(grid.column_angle);
  map.values.resize(grid.rows, grid.columns);
  for (int i = 0; i < grid.rows; ++i) {
    for (int j = 0; j < grid.columns; ++j) {
      map.values(i, j) = sms.variation(grid.index(i, j)) / kMicrometre;
    }
  }
  map.colour_min = limits.lower / kMicrometre;
  map.colour_max = limits.upper / kMicrometre;
  const std::string low = inner ? "ei/2 " : "EI/2 ";
  const std::string high = inner ? "es/2 " : "ES/2 ";
  map.colour_marks = {{limits.lower / kMicrometre, low + Micrometres(limits.lower)},
                      {limits.upper / kMicrometre, high + Micrometres(limits.upper)}};
  map.y_tic_step = 90.0;
  return map;
}

HeatMap MakeToleranceSpaceMap(const PartSpec& inner, const PartSpec& outer,
                              const ToleranceSpaceGrid& space, const std::string& where) {
  if (space.axial.size() < 2 || space.angle.size() < 2 ||
      space.value.rows() != space.axial.size() || space.value.cols() != space.angle.size()) {
    throw UserError("the tolerance space " + where +
                    " cannot be drawn: it needs at least 2 x 2 overlapping cells");
  }
  const RadialLimits limits = ToleranceSpaceLimits(inner, outer);
  HeatMap map;
  map.title = "tolerance space S_T = V_" + outer.name + " − V_" + inner.name + " " + where;
  map.x_label = "axial position (mm)";
  map.y_label = "direction angle (°)";
  map.colour_label = "S_T (µm)";
  map.x = space.axial / kMillimetre;
  map.y = Degrees(space.angle);
  map.values = space.value / kMicrometre;
  map.colour_min = limits.lower / kMicrometre;
  map.colour_max = limits.upper / kMicrometre;
  const auto describe = [](double value, bool smallest) {
    if (value < 0.0) return std::string(smallest ? "max interference " : "min interference ");
    return std::string(smallest ? "min clearance " : "max clearance ");
  };
  map.colour_marks = {
      {limits.lower / kMicrometre, describe(limits.lower, true) + Micrometres(limits.lower)},
      {limits.upper / kMicrometre, describe(limits.upper, false) + Micrometres(limits.upper)}};
  if (limits.lower < 0.0 && limits.upper > 0.0) map.colour_marks.push_back({0.0, "contact 0"});
  map.y_tic_step = 90.0;
  return map;
}

HeatMapChart MakeSmsChart(const std::string& scenario, std::vector<HeatMap> maps) {
  if (maps.empty()) throw UserError("nothing to draw for scenario '" + scenario + "'");
  HeatMapChart chart;
  chart.title = "Skin model shapes of " + scenario;
  chart.subtitle = {
      "V: radial deviation from nominal (> 0: shaft fatter, bore wider) · "
      "S_T: radial clearance (< 0: interference)",
      "colour bars span the tolerance limits"};
  chart.panels = std::move(maps);
  return chart;
}

}  // namespace fitfeel::plot
