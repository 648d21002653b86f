#include "surfaces/conical/conical_discretizer.h"

#include <cmath>

#include "framework/model/surface_of_revolution.h"
#include "surfaces/conical/conical_geometry.h"

namespace fitfeel::conical {

GridShape ConicalDiscretizer::DoShape(const PartSpec& part, const Resolution& resolution) const {
  const ConicalGeometry& geometry = GeometryOf(part);
  revolution::AutoResolution automatic;
  automatic.row_pitch = 2e-3;
  // An axis needs three sections to be anything but straight.
  return revolution::CheckedGridShape(part, resolution, geometry.length(), automatic, "a cone", 3);
}

SurfaceGrid ConicalDiscretizer::DoDiscretize(const PartSpec& part,
                                             const Resolution& resolution) const {
  const ConicalGeometry& geometry = GeometryOf(part);
  const GridShape shape = DoShape(part, resolution);
  const int rows = shape.rows, columns = shape.columns;
  SurfaceGrid grid = revolution::EmptyGrid(shape);
  const double h = geometry.length() / rows;
  const double alpha = geometry.half_angle();
  // Radius grows towards +t on the pin and shrinks towards +y in the hole, so the normal away
  // from the axis leans back along the axis on the pin and forward in the hole.
  const double axial_normal = (part.role == Role::kInner ? -1.0 : 1.0) * std::sin(alpha);
  for (int i = 0; i < rows; ++i) {
    const double y = (i + 0.5) * h;
    grid.row_position(i) = y;
    const double radius = 0.5 * geometry.DiameterAt(y);
    for (int j = 0; j < columns; ++j) {
      const int k = grid.index(i, j);
      const double c = std::cos(grid.column_angle(j)), s = std::sin(grid.column_angle(j));
      grid.centre.col(k) << radius * c, y, radius * s;
      grid.normal.col(k) << std::cos(alpha) * c, axial_normal, std::cos(alpha) * s;
      grid.area(k) = 2.0 * M_PI * radius / columns * h / std::cos(alpha);
    }
  }
  return grid;
}

}  // namespace fitfeel::conical
