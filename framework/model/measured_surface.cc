#include "framework/model/measured_surface.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// v0 + t (v1 - v0) with t = (x - x0) / (x1 - x0): at x == x0 exactly v0 (t = 0 adds a zero).
double Lerp(double x, double x0, double x1, double v0, double v1) {
  const double t = (x - x0) / (x1 - x0);
  return v0 + t * (v1 - v0);
}

// Value at `x` of the samples (xs ascending, distinct), held constant beyond the ends.
double HeldLinear(const std::vector<double>& xs, const std::vector<double>& vs, double x) {
  if (x <= xs.front()) return vs.front();
  if (x >= xs.back()) return vs.back();
  const auto hi = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
  return Lerp(x, xs[hi - 1], xs[hi], vs[hi - 1], vs[hi]);
}

// Value at angle `a` in [0, 2 pi) of samples at angles `as` (ascending, distinct, in [0, 2 pi))
// on a circle: between the last and the first sample the interpolation wraps around.
double PeriodicLinear(const std::vector<double>& as, const std::vector<double>& vs, double a) {
  const std::size_t k = as.size();
  if (k == 1) return vs.front();
  const auto hi = static_cast<std::size_t>(std::upper_bound(as.begin(), as.end(), a) - as.begin());
  if (hi == 0) return Lerp(a, as[k - 1] - kTwoPi, as[0], vs[k - 1], vs[0]);
  if (hi == k) return Lerp(a, as[k - 1], as[0] + kTwoPi, vs[k - 1], vs[0]);
  return Lerp(a, as[hi - 1], as[hi], vs[hi - 1], vs[hi]);
}

// Samples grouped by one coordinate (`key`), each group sorted by the other (`along`).
struct Trace {
  double key = 0.0;
  std::vector<double> along, value;
};

std::vector<Trace> GroupIntoTraces(const std::vector<double>& key, const std::vector<double>& along,
                                   const std::vector<double>& value) {
  std::vector<std::size_t> order(key.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return key[a] != key[b] ? key[a] < key[b] : along[a] < along[b];
  });
  std::vector<Trace> traces;
  for (std::size_t s : order) {
    if (traces.empty() || traces.back().key != key[s]) traces.push_back({key[s], {}, {}});
    traces.back().along.push_back(along[s]);
    traces.back().value.push_back(value[s]);
  }
  return traces;
}

using Matrix = Eigen::MatrixXd;
using Interpolation = double (*)(const std::vector<double>&, const std::vector<double>&, double);

// Resamples each trace at `along_at` with `along`, then across the traces (at their keys) at
// `across_at` with `across`: element (a, k) is the value at along_at(a), across_at(k).
Matrix ResampleTraces(const std::vector<Trace>& traces, const Eigen::VectorXd& along_at,
                      Interpolation along, const Eigen::VectorXd& across_at,
                      Interpolation across) {
  std::vector<double> keys;
  std::vector<std::vector<double>> at(static_cast<std::size_t>(along_at.size()));
  for (const Trace& t : traces) {
    keys.push_back(t.key);
    for (Eigen::Index a = 0; a < along_at.size(); ++a) {
      at[static_cast<std::size_t>(a)].push_back(along(t.along, t.value, along_at(a)));
    }
  }
  Matrix out(along_at.size(), across_at.size());
  for (Eigen::Index a = 0; a < along_at.size(); ++a) {
    for (Eigen::Index k = 0; k < across_at.size(); ++k) {
      out(a, k) = across(keys, at[static_cast<std::size_t>(a)], across_at(k));
    }
  }
  return out;
}

// Nearest grid column to angle a (periodic), columns ascending in [0, 2 pi).
int NearestColumn(const Eigen::VectorXd& angles, double a) {
  const int n = static_cast<int>(angles.size());
  const auto* begin = angles.data();
  const int hi = static_cast<int>(std::upper_bound(begin, begin + n, a) - begin);
  const int lo = hi == 0 ? n - 1 : hi - 1;
  const int up = hi == n ? 0 : hi;
  auto distance = [&](int j) {
    const double d = std::abs(a - angles(j));
    return std::min(d, kTwoPi - d);
  };
  return distance(lo) <= distance(up) ? lo : up;
}

Eigen::VectorXd FromPoints(const MeasuredSurface& m, const SurfaceGrid& grid,
                           const std::vector<double>& deviation) {
  const int rows = grid.rows, columns = grid.columns;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(grid.size());
  Eigen::VectorXi count = Eigen::VectorXi::Zero(grid.size());
  std::vector<double> boundaries;  // halfway between neighbouring rows
  for (int i = 1; i < rows; ++i) {
    boundaries.push_back(0.5 * (grid.row_position(i - 1) + grid.row_position(i)));
  }
  for (std::size_t s = 0; s < deviation.size(); ++s) {
    const int i = static_cast<int>(
        std::upper_bound(boundaries.begin(), boundaries.end(), m.height[s]) - boundaries.begin());
    const int c = grid.index(i, NearestColumn(grid.column_angle, m.angle[s]));
    sum(c) += deviation[s];
    ++count(c);
  }
  Eigen::VectorXd v = Eigen::VectorXd::Zero(grid.size());
  std::vector<char> row_filled(static_cast<std::size_t>(rows), 0);
  for (int i = 0; i < rows; ++i) {
    std::vector<double> as, vs;
    for (int j = 0; j < columns; ++j) {
      const int c = grid.index(i, j);
      if (count(c) > 0) {
        as.push_back(grid.column_angle(j));
        vs.push_back(sum(c) / count(c));
      }
    }
    if (as.empty()) continue;
    row_filled[static_cast<std::size_t>(i)] = 1;
    for (int j = 0; j < columns; ++j) {
      const int c = grid.index(i, j);
      v(c) = count(c) > 0 ? sum(c) / count(c) : PeriodicLinear(as, vs, grid.column_angle(j));
    }
  }
  std::vector<double> ys;
  std::vector<int> filled;
  for (int i = 0; i < rows; ++i) {
    if (row_filled[static_cast<std::size_t>(i)]) {
      ys.push_back(grid.row_position(i));
      filled.push_back(i);
    }
  }
  for (int i = 0; i < rows; ++i) {
    if (row_filled[static_cast<std::size_t>(i)]) continue;
    for (int j = 0; j < columns; ++j) {
      std::vector<double> vs;
      for (int f : filled) vs.push_back(v(grid.index(f, j)));
      v(grid.index(i, j)) = HeldLinear(ys, vs, grid.row_position(i));
    }
  }
  return v;
}

}  // namespace

bool IsCylinderGrid(const SurfaceGrid& grid, double radius) {
  for (int c = 0; c < grid.size(); ++c) {
    const double r = std::hypot(grid.centre(0, c), grid.centre(2, c));
    const double radial =
        (grid.normal(0, c) * grid.centre(0, c) + grid.normal(2, c) * grid.centre(2, c)) / r;
    if (!(std::abs(r - radius) <= 1e-9 * radius) || !(std::abs(radial - 1.0) <= 1e-9)) {
      return false;
    }
  }
  for (int j = 1; j < grid.columns; ++j) {
    if (!(grid.column_angle(j) > grid.column_angle(j - 1))) return false;
  }
  return true;
}

const char* MeasurementKindName(MeasurementKind kind) {
  switch (kind) {
    case MeasurementKind::kRoundness:
      return "roundness";
    case MeasurementKind::kStraightness:
      return "straightness";
    case MeasurementKind::kPoints:
      return "points";
  }
  return "?";
}

SkinModelShape MeasuredSkinModelShape(const MeasuredSurface& m, const SurfaceGrid& grid,
                                      double nominal_radius) {
  if (m.value.empty() || m.height.size() != m.value.size() || m.angle.size() != m.value.size()) {
    throw UserError("measurement '" + m.file.string() + "' holds no samples");
  }
  if (!IsCylinderGrid(grid, nominal_radius)) {
    throw UnsupportedError(
        "measured parts need a cylindrical mating surface (every cell on the nominal radius, "
        "radial normals); this surface type's grid is not one, so its parts must be generated");
  }
  std::vector<double> deviation = m.value;
  if (m.absolute) {
    for (double& d : deviation) d -= nominal_radius;
  }
  Eigen::VectorXd v(grid.size());
  if (m.kind == MeasurementKind::kRoundness) {
    // Traces at heights, over the angle: around each trace, then between the heights.
    const Matrix along = ResampleTraces(GroupIntoTraces(m.height, m.angle, deviation),
                                        grid.column_angle, PeriodicLinear, grid.row_position,
                                        HeldLinear);
    for (int i = 0; i < grid.rows; ++i) {
      for (int j = 0; j < grid.columns; ++j) v(grid.index(i, j)) = along(j, i);
    }
  } else if (m.kind == MeasurementKind::kStraightness) {
    // Traces at angles, along the axis: along each trace, then between the angles.
    const Matrix along = ResampleTraces(GroupIntoTraces(m.angle, m.height, deviation),
                                        grid.row_position, HeldLinear, grid.column_angle,
                                        PeriodicLinear);
    for (int i = 0; i < grid.rows; ++i) {
      for (int j = 0; j < grid.columns; ++j) v(grid.index(i, j)) = along(i, j);
    }
  } else {
    v = FromPoints(m, grid, deviation);
  }

  SkinModelShape sms;
  sms.grid = grid;
  sms.variation = v;
  const double mean = v.mean();
  sms.dimension_part = Eigen::VectorXd::Constant(grid.size(), mean);
  sms.form_part = v.array() - mean;
  sms.surface_part = Eigen::VectorXd::Zero(grid.size());
  return sms;
}

std::string MeasurementCsv(const SkinModelShape& sms, const std::string& comment) {
  std::string text;
  std::size_t start = 0;
  while (start < comment.size()) {
    const std::size_t end = std::min(comment.find('\n', start), comment.size());
    text += "# " + comment.substr(start, end - start) + "\n";
    start = end + 1;
  }
  text += "height [m],angle [rad],deviation [m]\n";
  char buffer[32];
  auto number = [&](double x) {
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
    text.append(buffer, r.ptr);
  };
  const SurfaceGrid& g = sms.grid;
  for (int i = 0; i < g.rows; ++i) {
    for (int j = 0; j < g.columns; ++j) {
      number(g.row_position(i));
      text += ',';
      number(g.column_angle(j));
      text += ',';
      number(sms.variation(g.index(i, j)));
      text += '\n';
    }
  }
  return text;
}

}  // namespace fitfeel
