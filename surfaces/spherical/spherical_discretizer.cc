#include "surfaces/spherical/spherical_discretizer.h"

#include <cmath>

#include "framework/model/surface_of_revolution.h"
#include "surfaces/spherical/spherical_geometry.h"

namespace fitfeel::spherical {

GridShape SphericalDiscretizer::DoShape(const PartSpec& part, const Resolution& resolution) const {
  const SphericalGeometry& geometry = GeometryOf(part);
  revolution::AutoResolution automatic;
  automatic.row_pitch = 1e-3;
  // Two-point sizes pair antipodal cells (row m-1-i, column j+n/2).
  return revolution::CheckedGridShape(part, resolution, geometry.width(), automatic, "a sphere", 2);
}

SurfaceGrid SphericalDiscretizer::DoDiscretize(const PartSpec& part,
                                               const Resolution& resolution) const {
  const SphericalGeometry& geometry = GeometryOf(part);
  const GridShape shape = DoShape(part, resolution);
  const int rows = shape.rows, columns = shape.columns;
  SurfaceGrid grid = revolution::EmptyGrid(shape);
  const double a = geometry.radius();
  const double h = geometry.width() / rows;
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
