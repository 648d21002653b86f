#include "surfaces/cylindrical/cylindrical_discretizer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "surfaces/cylindrical/cylindrical_form_wavelengths.h"

namespace fitfeel::cylindrical {

const CylindricalGeometry& AsCylinder(const PartSpec& part) {
  const auto* geometry = dynamic_cast<const CylindricalGeometry*>(part.geometry.get());
  if (geometry == nullptr) {
    throw UserError("part '" + part.name + "' has no cylindrical geometry");
  }
  return *geometry;
}

Resolution CylindricalDiscretizer::AutoResolution(const CylindricalGeometry& geometry) {
  const double pitch = kMinFormWavelength / kSamplesPerWave;
  Resolution r;
  // The small allowance keeps l = 20 mm at 16 rows despite rounding in l / pitch.
  r.rows = std::max(kMinAutoRows, static_cast<int>(std::ceil(geometry.length() / pitch - 1e-9)));
  r.columns =
      std::max(kMinAutoColumns, kSamplesPerWave * MaxRoundnessHarmonic(geometry.diameter()));
  r.columns += r.columns % 2;
  return r;
}

GridShape CylindricalDiscretizer::DoShape(const PartSpec& part,
                                          const Resolution& resolution) const {
  const CylindricalGeometry& geometry = AsCylinder(part);
  const Resolution r = resolution.is_auto() ? AutoResolution(geometry) : resolution;
  if (r.rows < 1 || r.columns < 4 || r.columns % 2 != 0) {
    throw UserError("part '" + part.name +
                    "': a cylindrical grid needs at least 1 row and an even "
                    "number of columns >= 4 (each cell needs a diametrically opposite one for "
                    "two-point sizes); got " +
                    std::to_string(r.rows) + " x " + std::to_string(r.columns));
  }
  // 2e7 cells is ~1 GB of grid data: far beyond what any scene needs (see the benchmarks).
  if (static_cast<long>(r.rows) * r.columns > 20'000'000L) {
    throw UserError("part '" + part.name + "': a " + std::to_string(r.rows) + " x " +
                    std::to_string(r.columns) + " grid exceeds the limit of 2e7 cells");
  }
  return GridShape{r.rows, r.columns};
}

SurfaceGrid CylindricalDiscretizer::DoDiscretize(const PartSpec& part,
                                                 const Resolution& resolution) const {
  const CylindricalGeometry& geometry = AsCylinder(part);
  const GridShape r = DoShape(part, resolution);
  SurfaceGrid g;
  g.rows = r.rows;
  g.columns = r.columns;
  const double radius = geometry.diameter() / 2.0;
  const double pitch = geometry.length() / g.rows;
  g.row_position.resize(g.rows);
  for (int i = 0; i < g.rows; ++i) g.row_position(i) = (i + 0.5) * pitch;
  g.column_angle.resize(g.columns);
  for (int j = 0; j < g.columns; ++j) g.column_angle(j) = 2.0 * std::numbers::pi * j / g.columns;
  g.centre.resize(3, g.size());
  g.normal.resize(3, g.size());
  const double cell_area = std::numbers::pi * geometry.diameter() * geometry.length() / g.size();
  g.area = Eigen::VectorXd::Constant(g.size(), cell_area);
  // Every row has the same column directions: one cosine and sine per column, not per cell (at
  // the paper's 40 x 360 they were most of the discretization).
  std::vector<double> c(static_cast<std::size_t>(g.columns)), s(c.size());
  for (int j = 0; j < g.columns; ++j) {
    c[static_cast<std::size_t>(j)] = std::cos(g.column_angle(j));
    s[static_cast<std::size_t>(j)] = std::sin(g.column_angle(j));
  }
  for (int i = 0; i < g.rows; ++i) {
    for (int j = 0; j < g.columns; ++j) {
      const auto k = static_cast<std::size_t>(j);
      g.normal.col(g.index(i, j)) << c[k], 0.0, s[k];
      g.centre.col(g.index(i, j)) << radius * c[k], g.row_position(i), radius * s[k];
    }
  }
  return g;
}

}  // namespace fitfeel::cylindrical
