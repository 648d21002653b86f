#include "surfaces/conical/conical_discretizer.h"
#include "surfaces/conical/number_text.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/core/error.h"
#include "surfaces/conical/conical_geometry.h"

namespace fitfeel::conical {
namespace {

constexpr int kAutoColumns = 72;
constexpr double kAutoRowPitch = 2e-3;
constexpr int kMinAutoRows = 8;
constexpr int kMaxAutoRows = 400;

}  // namespace

SurfaceGrid ConicalDiscretizer::DoDiscretize(const PartSpec& part,
                                             const Resolution& resolution) const {
  const ConicalGeometry& geometry = GeometryOf(part);
  int rows = resolution.rows;
  int columns = resolution.columns;
  if (resolution.is_auto()) {
    rows = std::clamp(static_cast<int>(std::ceil(geometry.length() / kAutoRowPitch)), kMinAutoRows,
                      kMaxAutoRows);
    columns = kAutoColumns;
  }
  // Two-point sizes pair opposite columns, and a minimum-zone circle needs at least four points
  // on each side; an axis needs three sections to be anything but straight.
  if (columns < 8 || columns % 2 != 0) {
    throw UserError("part '" + part.name + "': a cone needs an even number of columns >= 8, not " +
                    NumberText(columns));
  }
  if (rows < 3) {
    throw UserError("part '" + part.name + "': a cone needs at least 3 rows, not " +
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
  const double h = geometry.length() / rows;
  const double alpha = geometry.half_angle();
  // Radius grows towards +t on the pin and shrinks towards +y in the hole, so the normal away
  // from the axis leans back along the axis on the pin and forward in the hole.
  const double axial_normal = (part.role == Role::kInner ? -1.0 : 1.0) * std::sin(alpha);
  for (int j = 0; j < columns; ++j) grid.column_angle(j) = 2.0 * M_PI * j / columns;
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
