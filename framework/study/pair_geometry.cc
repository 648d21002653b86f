#include "framework/study/pair_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace fitfeel::study {
namespace {

// Radius of the nominal cylinder the grid's cell centres lie on, if they all lie on one.
std::optional<double> CylinderRadius(const SurfaceGrid& grid) {
  if (grid.size() == 0 || grid.centre.cols() != grid.size()) return std::nullopt;
  double lo = std::numeric_limits<double>::infinity();
  double hi = 0.0;
  for (int k = 0; k < grid.size(); ++k) {
    const double r = std::hypot(grid.centre(0, k), grid.centre(2, k));
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  if (!(lo > 0.0) || hi - lo > 1e-9 * hi) return std::nullopt;
  return 0.5 * (lo + hi);
}

// Per column, the extreme actual radius over the rows: largest for the inner part, smallest for
// the outer one.
std::vector<double> ColumnEnvelope(const SkinModelShape& sms, double radius, bool largest) {
  const SurfaceGrid& g = sms.grid;
  std::vector<double> out(static_cast<std::size_t>(g.columns),
                          largest ? -std::numeric_limits<double>::infinity()
                                  : std::numeric_limits<double>::infinity());
  for (int i = 0; i < g.rows; ++i) {
    for (int j = 0; j < g.columns; ++j) {
      const double r = radius + sms.variation(g.index(i, j));
      double& e = out[static_cast<std::size_t>(j)];
      e = largest ? std::max(e, r) : std::min(e, r);
    }
  }
  return out;
}

// Periodic linear interpolation of `values` given at `angles` (increasing, within one turn).
double AtAngle(const Eigen::VectorXd& angles, const std::vector<double>& values, double angle) {
  const int n = static_cast<int>(values.size());
  const double turn = 2.0 * std::numbers::pi;
  double a = std::fmod(angle - angles(0), turn);
  if (a < 0.0) a += turn;
  a += angles(0);
  for (int j = 0; j < n; ++j) {
    const double a0 = angles(j);
    const double a1 = j + 1 < n ? angles(j + 1) : angles(0) + turn;
    if (a >= a0 && a <= a1) {
      const double v1 = values[static_cast<std::size_t>((j + 1) % n)];
      const double t = a1 > a0 ? (a - a0) / (a1 - a0) : 0.0;
      return values[static_cast<std::size_t>(j)] * (1.0 - t) + v1 * t;
    }
  }
  return values.back();  // only for angles at the seam within rounding
}

}  // namespace

PairGeometry MeasurePair(const SkinModelShape& inner, const SkinModelShape& outer) {
  PairGeometry out;
  if (inner.dimension_part.size() > 0) out.inner_size = 2.0 * inner.dimension_part.mean();
  if (outer.dimension_part.size() > 0) out.outer_size = 2.0 * outer.dimension_part.mean();
  const auto ri = CylinderRadius(inner.grid);
  const auto ro = CylinderRadius(outer.grid);
  if (!ri || !ro || inner.grid.columns < 3 || outer.grid.columns < 3) return out;
  const std::vector<double> shaft = ColumnEnvelope(inner, *ri, true);
  const std::vector<double> bore = ColumnEnvelope(outer, *ro, false);
  // Radial room in each direction of the inner grid's columns.
  std::vector<double> room(shaft.size());
  for (std::size_t j = 0; j < shaft.size(); ++j) {
    room[j] = AtAngle(outer.grid.column_angle, bore, inner.grid.column_angle(static_cast<int>(j))) -
              shaft[j];
  }
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < room.size(); ++j) {
    const double across = room[j] + AtAngle(inner.grid.column_angle, room,
                                            inner.grid.column_angle(static_cast<int>(j)) +
                                                std::numbers::pi);
    least = std::min(least, across);
  }
  out.min_clearance = least;
  return out;
}

}  // namespace fitfeel::study
