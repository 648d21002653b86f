#include "surfaces/planar/planar_characteristics.h"

#include <algorithm>
#include <limits>

#include "surfaces/planar/planar_geometry.h"

namespace fitfeel::planar {

FaceSamples SamplesOf(const SurfaceGrid& grid, const FaceLayout& layout, int face,
                      const Eigen::VectorXd& values) {
  FaceSamples s;
  const int strips = layout.columns_per_face;
  const int cells = grid.rows * strips;
  s.y.reserve(cells);
  s.across.reserve(cells);
  s.v.reserve(cells);
  const int across_axis = face < 2 ? 2 : 0;
  for (int i = 0; i < grid.rows; ++i) {
    for (int q = 0; q < strips; ++q) {
      const int c = grid.index(i, face * strips + q);
      s.y.push_back(grid.centre(1, c));
      s.across.push_back(grid.centre(across_axis, c));
      s.v.push_back(values[c]);
    }
  }
  return s;
}

double FaceStraightness(const SurfaceGrid& grid, const FaceLayout& layout, int face,
                        const Eigen::VectorXd& values) {
  double worst = 0.0;
  std::vector<double> y(grid.rows), v(grid.rows);
  for (int q = 0; q < layout.columns_per_face; ++q) {
    const int column = face * layout.columns_per_face + q;
    for (int i = 0; i < grid.rows; ++i) {
      y[i] = grid.row_position[i];
      v[i] = values[grid.index(i, column)];
    }
    worst = std::max(worst, MinZoneStraightness(y, v).width);
  }
  return worst;
}

PlaneZone FaceFlatness(const SurfaceGrid& grid, const FaceLayout& layout, int face,
                       const Eigen::VectorXd& values) {
  const FaceSamples s = SamplesOf(grid, layout, face, values);
  return MinZoneFlatness(s.y, s.across, s.v);
}

double PairParallelism(const SurfaceGrid& grid, const FaceLayout& layout, int pair,
                       const Eigen::VectorXd& values) {
  double worst = 0.0;
  for (int k = 0; k < 2; ++k) {
    const int face = 2 * pair + k;
    const int datum = 2 * pair + (1 - k);
    const PlaneZone d = FaceFlatness(grid, layout, datum, values);
    const FaceSamples s = SamplesOf(grid, layout, face, values);
    worst = std::max(worst, RangeAlong(s.y, s.across, s.v, -d.slope_y, -d.slope_z));
  }
  return worst;
}

double PairAxisStraightness(const SurfaceGrid& grid, const FaceLayout& layout, int pair,
                            const Eigen::VectorXd& values) {
  double worst = 0.0;
  std::vector<double> y(grid.rows), m(grid.rows);
  const int strips = layout.columns_per_face;
  for (int q = 0; q < strips; ++q) {
    for (int i = 0; i < grid.rows; ++i) {
      y[i] = grid.row_position[i];
      m[i] = 0.5 * (values[grid.index(i, 2 * pair * strips + q)] -
                    values[grid.index(i, (2 * pair + 1) * strips + q)]);
    }
    worst = std::max(worst, MinZoneStraightness(y, m).width);
  }
  return worst;
}

std::vector<CharacteristicCheck> EvaluatePlanarCharacteristics(const PartSpec& part,
                                                               const SkinModelShape& sms) {
  const SurfaceGrid& grid = sms.grid;
  const FaceLayout layout = LayoutOf(grid);
  const double b = part.size.nominal;
  double smallest = std::numeric_limits<double>::infinity();
  double largest = -smallest;
  for (int i = 0; i < grid.rows; ++i) {
    for (int j = 0; j < grid.columns; ++j) {
      if (layout.face_of(j) % 2 != 0) continue;
      const double size =
          b + sms.variation[grid.index(i, j)] + sms.variation[grid.index(i, layout.opposite(j))];
      smallest = std::min(smallest, size);
      largest = std::max(largest, size);
    }
  }
  const double lower = b + part.size.lower_deviation;
  const double upper = b + part.size.upper_deviation;
  std::vector<CharacteristicCheck> checks{{"two_point_size_min", smallest, lower, upper},
                                          {"two_point_size_max", largest, lower, upper}};
  const auto& tol = part.form.tolerance;
  if (auto it = tol.find(FormCharacteristic::kStraightness); it != tol.end()) {
    double worst = 0.0;
    for (int f = 0; f < layout.faces; ++f) {
      worst = std::max(worst, FaceStraightness(grid, layout, f, sms.variation));
    }
    checks.push_back({"straightness", worst, 0.0, it->second});
  }
  if (auto it = tol.find(FormCharacteristic::kFlatness); it != tol.end()) {
    double worst = 0.0;
    for (int f = 0; f < layout.faces; ++f) {
      worst = std::max(worst, FaceFlatness(grid, layout, f, sms.variation).width);
    }
    checks.push_back({"flatness", worst, 0.0, it->second});
  }
  if (auto it = tol.find(FormCharacteristic::kParallelism); it != tol.end()) {
    double worst = 0.0;
    for (int p = 0; p < layout.faces / 2; ++p) {
      worst = std::max(worst, PairParallelism(grid, layout, p, sms.variation));
    }
    checks.push_back({"parallelism", worst, 0.0, it->second});
  }
  if (auto it = tol.find(FormCharacteristic::kAxisStraightness); it != tol.end()) {
    double worst = 0.0;
    for (int p = 0; p < layout.faces / 2; ++p) {
      worst = std::max(worst, PairAxisStraightness(grid, layout, p, sms.variation));
    }
    checks.push_back({"axis_straightness", worst, 0.0, it->second});
  }
  return checks;
}

}  // namespace fitfeel::planar
