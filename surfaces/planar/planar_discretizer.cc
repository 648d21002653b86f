#include "surfaces/planar/planar_discretizer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "framework/core/error.h"
#include "surfaces/planar/planar_geometry.h"

namespace fitfeel::planar {
namespace {

// The paper puts form wavelengths above 10 mm; four cells per shortest wavelength sample a wave's
// peaks, troughs and flanks, so a 2.5 mm cell pitch resolves every form the generator can draw.
constexpr double kAutoPitch = 2.5e-3;
// Across the height, three strips give each face a second dimension for flatness (a twist or a
// bow across the face) even on a low key flank.
constexpr int kMinAutoStrips = 3;
constexpr int kMinAutoRows = 4;
constexpr int kMaxAutoCells = 4000;

}  // namespace

double FaceAngle(int face) {
  constexpr double kPi = std::numbers::pi;
  switch (face) {
    case 0:
      return 0.0;
    case 1:
      return kPi;
    case 2:
      return 0.5 * kPi;
    default:
      return 1.5 * kPi;
  }
}

FaceLayout LayoutOf(const SurfaceGrid& grid) {
  FaceLayout layout;
  const int n = grid.columns;
  if (grid.column_angle.size() != n || n < 2) {
    throw UserError("planar grid: expected at least two columns with direction angles");
  }
  // Faces change where the direction angle does; every face has the same number of strips.
  int strips = 1;
  while (strips < n && grid.column_angle[strips] == grid.column_angle[0]) ++strips;
  layout.columns_per_face = strips;
  layout.faces = n / strips;
  if ((layout.faces != 2 && layout.faces != 4) || layout.faces * strips != n) {
    throw UserError("planar grid: columns do not split into 2 or 4 equal faces");
  }
  for (int j = 0; j < n; ++j) {
    if (std::abs(grid.column_angle[j] - FaceAngle(layout.face_of(j))) > 1e-12) {
      throw UserError("planar grid: column " + std::to_string(j) +
                      " has a direction angle that is not its face's normal");
    }
  }
  return layout;
}

GridShape PlanarDiscretizer::DoShape(const PartSpec& part, const Resolution& resolution) const {
  const PlanarGeometry& g = PlanarGeometryOf(part);
  const int faces = g.faces();
  int rows = 0;
  int strips = 0;
  if (resolution.is_auto()) {
    rows = std::max(kMinAutoRows, static_cast<int>(std::ceil(g.length() / kAutoPitch - 1e-9)));
    strips = std::max(kMinAutoStrips, static_cast<int>(std::ceil(g.height() / kAutoPitch - 1e-9)));
    if (static_cast<long>(rows) * strips * faces > kMaxAutoCells) {
      throw UserError("part '" + part.name + "': the automatic grid would exceed " +
                      std::to_string(kMaxAutoCells) + " cells; give model.resolution");
    }
  } else {
    rows = resolution.rows;
    if (resolution.columns % faces != 0) {
      throw UserError("part '" + part.name + "': resolution columns (" +
                      std::to_string(resolution.columns) + ") must be a multiple of its " +
                      std::to_string(faces) + " faces");
    }
    strips = resolution.columns / faces;
  }
  return GridShape{rows, faces * strips};
}

SurfaceGrid PlanarDiscretizer::DoDiscretize(const PartSpec& part,
                                            const Resolution& resolution) const {
  const PlanarGeometry& g = PlanarGeometryOf(part);
  const GridShape shape = DoShape(part, resolution);
  const int rows = shape.rows;
  const int strips = shape.columns / g.faces();
  SurfaceGrid grid;
  grid.rows = rows;
  grid.columns = shape.columns;
  const int cells = grid.size();
  const double dy = g.length() / rows;
  const double dz = g.height() / strips;
  grid.row_position.resize(rows);
  for (int i = 0; i < rows; ++i) grid.row_position[i] = (i + 0.5) * dy;
  grid.column_angle.resize(grid.columns);
  grid.centre.resize(3, cells);
  grid.normal.resize(3, cells);
  grid.area = Eigen::VectorXd::Constant(cells, dy * dz);
  const double half = 0.5 * g.width();
  for (int j = 0; j < grid.columns; ++j) {
    const int face = j / strips;
    grid.column_angle[j] = FaceAngle(face);
    const double across = -0.5 * g.height() + (j % strips + 0.5) * dz;
    const double sign = (face % 2 == 0) ? 1.0 : -1.0;
    for (int i = 0; i < rows; ++i) {
      const int c = grid.index(i, j);
      const double y = grid.row_position[i];
      if (face < 2) {
        grid.centre.col(c) << sign * half, y, across;
        grid.normal.col(c) << sign, 0.0, 0.0;
      } else {
        grid.centre.col(c) << across, y, sign * half;
        grid.normal.col(c) << 0.0, 0.0, sign;
      }
    }
  }
  return grid;
}

}  // namespace fitfeel::planar
