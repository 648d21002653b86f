#include "surfaces/spherical/spherical_discretizer.h"
#include "surfaces/spherical/number_text.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/core/error.h"
#include "surfaces/spherical/spherical_geometry.h"

namespace fitfeel::spherical {
namespace {

constexpr int kAutoColumns = 72;
constexpr double kAutoRowPitch = 1e-3;
constexpr int kMinAutoRows = 8;
constexpr int kMaxAutoRows = 400;

}  // namespace

SurfaceGrid SphericalDiscretizer::DoDiscretize(const PartSpec& part,
                                               const Resolution& resolution) const {
  const SphericalGeometry& geometry = GeometryOf(part);
  int rows = resolution.rows;
  int columns = resolution.columns;
  if (resolution.is_auto()) {
    rows = std::clamp(static_cast<int>(std::ceil(geometry.width() / kAutoRowPitch)), kMinAutoRows,
                      kMaxAutoRows);
    columns = kAutoColumns;
  }
  // Two-point sizes pair antipodal cells (row m-1-i, column j+n/2); a minimum-zone circle needs
  // at least four points on each side.
  if (columns < 8 || columns % 2 != 0) {
    throw UserError("part '" + part.name +
                    "': a sphere needs an even number of columns >= 8, not " + NumberText(columns));
  }
  if (rows < 2) {
    throw UserError("part '" + part.name + "': a sphere needs at least 2 rows, not " +
                    NumberText(rows));
  }
  SurfaceGrid grid;
  grid.rows = rows;
  grid.columns = columns;
  grid.row_position.resize(rows);
  grid.column_angle.resize(columns);
  grid.centre.resize(3, rows * columns);
  grid.normal.resize(3, rows * columns);
  grid.area.resize(rows * columns);
  const double a = geometry.radius();
  const double h = geometry.width() / rows;
  for (int j = 0; j < columns; ++j) grid.column_angle(j) = 2.0 * M_PI * j / columns;
  for (int i = 0; i < rows; ++i) {
    const double y = -0.5 * geometry.width() + (i + 0.5) * h;
    grid.row_position(i) = y;
    const double rho = std::sqrt(a * a - y * y);  // distance from the axis
    for (int j = 0; j < columns; ++j) {
      const int k = grid.index(i, j);
      const double c = std::cos(grid.column_angle(j)), s = std::sin(grid.column_angle(j));
      grid.centre.col(k) << rho * c, y, rho * s;
      grid.normal.col(k) = grid.centre.col(k) / a;
      grid.area(k) = 2.0 * M_PI * a * h / columns;
    }
  }
  return grid;
}

}  // namespace fitfeel::spherical
