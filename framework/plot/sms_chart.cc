#include "framework/plot/sms_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "framework/core/error.h"

namespace fitfeel::plot {

namespace {

constexpr double kMicrometre = 1e-6;
constexpr double kMillimetre = 1e-3;
constexpr double kDegree = std::numbers::pi / 180.0;

std::string Micrometres(double metres) {
  char buffer[48];
  // + 0.0 turns an ISO table's -0 deviation into +0.
  std::snprintf(buffer, sizeof buffer, "%+.2f µm", metres / kMicrometre + 0.0);
  return buffer;
}

std::string SizeText(const PartSpec& part) {
  char buffer[96];
  if (!part.size.iso_code.empty()) {
    std::snprintf(buffer, sizeof buffer, "%g mm %s", part.size.nominal / kMillimetre,
                  part.size.iso_code.c_str());
  } else {
    std::snprintf(buffer, sizeof buffer, "%g mm %+g/%+g µm", part.size.nominal / kMillimetre,
                  part.size.lower_deviation / kMicrometre + 0.0,
                  part.size.upper_deviation / kMicrometre + 0.0);
  }
  return buffer;
}

// Angles in degrees on [0, 360): the map's vertical axis then reads as a compass around the axis.
Eigen::VectorXd Degrees(const Eigen::VectorXd& radians) { return radians / kDegree; }

bool StrictlyIncreasing(const Eigen::VectorXd& v) {
  for (Eigen::Index k = 1; k < v.size(); ++k) {
    if (!(v(k) > v(k - 1))) return false;
  }
  return v.size() > 0;
}

}  // namespace

void SetColumnAxis(const Eigen::VectorXd& angles, HeatMap* map) {
  if (StrictlyIncreasing(angles)) {
    map->y = Degrees(angles);
    map->y_label = "direction angle (°)";
    map->y_tic_step = 90.0;
  } else {
    map->y = Eigen::VectorXd::LinSpaced(angles.size(), 0.0, static_cast<double>(angles.size() - 1));
    map->y_label = "column (face by face)";
    map->y_tic_step = 0.0;
  }
}

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
  map.colour_label = "V (µm)";
  map.x = grid.row_position / kMillimetre;
  SetColumnAxis(grid.column_angle, &map);
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
  return map;
}

namespace {

// Row boundaries of a grid along its own axial coordinate (rows + 1 values).
std::vector<double> RowEdges(const SurfaceGrid& grid) {
  const Eigen::VectorXd& y = grid.row_position;
  const int m = grid.rows;
  std::vector<double> edges(static_cast<std::size_t>(m) + 1);
  edges[0] = y(0) - 0.5 * (y(1) - y(0));
  for (int i = 1; i < m; ++i) edges[static_cast<std::size_t>(i)] = 0.5 * (y(i - 1) + y(i));
  edges[static_cast<std::size_t>(m)] = y(m - 1) + 0.5 * (y(m - 1) - y(m - 2));
  return edges;
}

void CheckGrid(const SkinModelShape& sms, const char* which) {
  const SurfaceGrid& g = sms.grid;
  if (g.rows < 2 || g.columns < 2 || g.row_position.size() != g.rows ||
      g.column_angle.size() != g.columns || sms.variation.size() != g.size()) {
    throw UserError(std::string("the ") + which +
                    " part's skin model shape needs at least 2 x 2 cells and one variation per "
                    "cell for a tolerance-space map");
  }
}

// Row holding coordinate `y` (clamped to the grid).
int RowAt(const std::vector<double>& edges, double y) {
  const auto it = std::upper_bound(edges.begin(), edges.end(), y);
  const int row = static_cast<int>(it - edges.begin()) - 1;
  return std::clamp(row, 0, static_cast<int>(edges.size()) - 2);
}

// Rows meeting the interval (low, high); a row that only touches an end (to rounding) does not
// count.
int RowsIn(const std::vector<double>& edges, double low, double high) {
  const double slack = 1e-9 * (edges.back() - edges.front());
  return std::max(1, RowAt(edges, high - slack) - RowAt(edges, low + slack) + 1);
}

// Angular distance on the circle.
double AngleGap(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 2.0 * std::numbers::pi);
  return std::min(d, 2.0 * std::numbers::pi - d);
}

}  // namespace

double MatingLength(const SurfaceGrid& grid) {
  if (grid.rows < 2 || grid.row_position.size() != grid.rows) {
    throw UserError("a mating length needs a grid of two rows or more");
  }
  const auto edges = RowEdges(grid);
  return edges.back() - edges.front();
}

double FullInsertionDepth(const SkinModelShape& inner, const SkinModelShape& outer) {
  return std::min(MatingLength(inner.grid), MatingLength(outer.grid));
}

ToleranceSpaceGrid ToleranceSpaceAtDepth(const SkinModelShape& inner, const SkinModelShape& outer,
                                         double depth, int samples_per_row) {
  CheckGrid(inner, "inner");
  CheckGrid(outer, "outer");
  if (samples_per_row < 1) throw std::invalid_argument("samples_per_row must be positive");
  const auto inner_edges = RowEdges(inner.grid);
  const auto outer_edges = RowEdges(outer.grid);
  const double inner_length = inner_edges.back() - inner_edges.front();
  const double outer_length = outer_edges.back() - outer_edges.front();
  // Overlap in "distance past the outer part's entrance".
  const double low = std::max(depth - inner_length, 0.0);
  const double high = std::min(depth, outer_length);
  if (!(high > low)) {
    char text[64];
    std::snprintf(text, sizeof text, "%g mm", depth / kMillimetre);
    throw UserError("the mating surfaces do not overlap at depth " + std::string(text));
  }
  const auto inner_coordinate = [&](double past_entrance) {
    return inner_edges.back() - (depth - past_entrance);
  };
  const auto outer_coordinate = [&](double past_entrance) {
    return outer_edges.front() + past_entrance;
  };
  const int rows = std::max(RowsIn(inner_edges, inner_coordinate(low), inner_coordinate(high)),
                            RowsIn(outer_edges, outer_coordinate(low), outer_coordinate(high)));
  const int samples = std::max(2, std::min(4000, samples_per_row * rows));

  const SurfaceGrid& ig = inner.grid;
  const SurfaceGrid& og = outer.grid;
  // Columns face each other one to one when the grids share their angles (surfaces of revolution
  // of equal n, or flat faces split alike); otherwise by nearest direction angle around the axis.
  std::vector<int> facing(static_cast<std::size_t>(ig.columns));
  const bool same_columns =
      ig.columns == og.columns && (ig.column_angle - og.column_angle).cwiseAbs().maxCoeff() < 1e-12;
  if (!same_columns &&
      !(StrictlyIncreasing(ig.column_angle) && StrictlyIncreasing(og.column_angle))) {
    throw UserError(
        "the parts' columns do not face each other (different flat-face layouts), so "
        "their tolerance space has no map");
  }
  for (int j = 0; j < ig.columns; ++j) {
    int best = j;
    if (!same_columns) {
      best = 0;
      for (int k = 1; k < og.columns; ++k) {
        if (AngleGap(og.column_angle(k), ig.column_angle(j)) <
            AngleGap(og.column_angle(best), ig.column_angle(j))) {
          best = k;
        }
      }
    }
    facing[static_cast<std::size_t>(j)] = best;
  }

  ToleranceSpaceGrid space;
  space.axial.resize(samples);
  space.angle = ig.column_angle;
  space.value.resize(samples, ig.columns);
  for (int s = 0; s < samples; ++s) {
    const double past_entrance = low + (s + 0.5) * (high - low) / samples;
    space.axial(s) = past_entrance;
    const int inner_row = RowAt(inner_edges, inner_coordinate(past_entrance));
    const int outer_row = RowAt(outer_edges, outer_coordinate(past_entrance));
    for (int j = 0; j < ig.columns; ++j) {
      space.value(s, j) =
          outer.variation(og.index(outer_row, facing[static_cast<std::size_t>(j)])) -
          inner.variation(ig.index(inner_row, j));
    }
  }
  return space;
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
  map.x_label = "distance past the " + outer.name + "'s entrance (mm)";
  map.colour_label = "S_T (µm)";
  map.x = space.axial / kMillimetre;
  SetColumnAxis(space.angle, &map);
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
  return map;
}

HeatMapChart MakeSmsChart(const std::string& scenario, std::vector<HeatMap> maps) {
  if (maps.empty()) throw UserError("nothing to draw for scenario '" + scenario + "'");
  HeatMapChart chart;
  chart.title = "Skin model shapes of " + scenario;
  chart.subtitle = {
      "V: radial deviation from nominal (> 0: shaft fatter, bore wider) · "
      "S_T: radial clearance (< 0: interference)",
      "labelled colour-bar tics: the size limits (half the diametral deviations) and their "
      "clearances"};
  chart.panels = std::move(maps);
  return chart;
}

}  // namespace fitfeel::plot
