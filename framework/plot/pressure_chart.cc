#include "framework/plot/pressure_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "framework/core/error.h"
#include "framework/plot/sms_chart.h"
#include "framework/plot/trace_chart.h"

namespace fitfeel::plot {

namespace {

std::string Millimetres(double value) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.3f mm", value);
  return buffer;
}

}  // namespace

DepthRange ConstrainedDepthRange(const ConstrainedTrace& trace) {
  if (trace.depth_mm.empty()) throw UserError("the trace has no constrained row");
  const auto [low, high] = std::minmax_element(trace.depth_mm.begin(), trace.depth_mm.end());
  return {*low, *high};
}

std::size_t RowAtDepth(const ConstrainedTrace& trace, double depth_mm) {
  const DepthRange range = ConstrainedDepthRange(trace);
  if (!std::isfinite(depth_mm) || depth_mm < range.min || depth_mm > range.max) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%g mm", depth_mm);
    throw UserError("depth " + std::string(buffer) +
                    " is outside the run's constrained depth range " + Millimetres(range.min) +
                    " to " + Millimetres(range.max));
  }
  std::size_t best = 0;
  for (std::size_t k = 1; k < trace.depth_mm.size(); ++k) {
    if (std::abs(trace.depth_mm[k] - depth_mm) < std::abs(trace.depth_mm[best] - depth_mm)) {
      best = k;
    }
  }
  return best;
}

HeatMapChart MakePressureChart(const PressureMapData& data) {
  const SurfaceGrid& grid = data.grid;
  if (grid.rows < 2 || grid.columns < 2 || data.interference.size() != grid.size()) {
    throw UserError("the interference map has " + std::to_string(data.interference.size()) +
                    " values for a grid of " + std::to_string(grid.rows) + " x " +
                    std::to_string(grid.columns) + " cells");
  }
  if (!(data.pressure_per_interference >= 0.0)) {
    throw UserError("the law's pressure per unit interference must not be negative");
  }
  HeatMap map;
  map.title = "contact pressure on the inner part at depth " + Millimetres(data.depth_mm);
  map.x_label = "axial position (mm)";
  map.colour_label = "contact pressure p (MPa)";
  map.x = grid.row_position * 1e3;
  SetColumnAxis(grid.column_angle, &map);
  const bool angle_axis = map.y_tic_step > 0.0;  // false: flat faces, columns by number
  map.values.resize(grid.rows, grid.columns);
  for (int i = 0; i < grid.rows; ++i) {
    for (int j = 0; j < grid.columns; ++j) {
      const double delta = std::max(0.0, data.interference(grid.index(i, j)));
      map.values(i, j) = data.pressure_per_interference * delta * 1e-6;
    }
  }
  map.colour_min = 0.0;
  const double radial = std::hypot(data.fx_N, data.fz_N);
  char direction[96] = "";
  if (radial > 0.0) {
    double angle = std::atan2(data.fz_N, data.fx_N) * (180.0 / std::numbers::pi);
    if (angle < 0.0) angle += 360.0;
    std::snprintf(direction, sizeof direction, " toward %.0f°", angle);
    if (angle_axis && angle >= map.y(0) && angle <= map.y(map.y.size() - 1)) {
      map.y_lines.push_back({angle, "radial force on the inner part"});
    }
  }
  HeatMapChart chart;
  chart.title =
      "Contact pressure of " + data.scenario + (data.law.empty() ? "" : " · law " + data.law);
  chart.subtitle = {"axial resistance F_y = " + FormatNewtons(data.fy_N) +
                    "     radial resistance F_r = " + FormatNewtons(radial) + direction};
  if (std::abs(data.force_depth_mm - data.depth_mm) > 1e-6) {
    chart.subtitle.push_back("(forces of the run's tick nearest this depth, at " +
                             Millimetres(data.force_depth_mm) + ")");
  }
  // An all-dark map otherwise reads as a drawing failure.
  if (!(map.values.maxCoeff() > 0.0)) {
    chart.subtitle.push_back("no interference at this pose: the parts are in clearance");
  }
  if (!data.pose_note.empty()) chart.subtitle.push_back(data.pose_note);
  chart.panels = {std::move(map)};
  return chart;
}

}  // namespace fitfeel::plot
