#include "framework/model/render_mesh.h"

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

void CheckGrid(const SurfaceGrid& grid) {
  if (grid.rows < 1 || grid.columns < 1 || grid.row_position.size() != grid.rows ||
      grid.centre.cols() != grid.size() || grid.normal.cols() != grid.size()) {
    throw UserError("render mesh: the grid is empty or its arrays do not match " +
                    std::to_string(grid.rows) + " x " + std::to_string(grid.columns) + " cells");
  }
}

// Edges of the rows along y: halfway between centres, the outer ends mirrored.
std::vector<double> RowEdges(const SurfaceGrid& grid, double single_row_half_pitch) {
  const int m = grid.rows;
  std::vector<double> edges(static_cast<std::size_t>(m) + 1);
  if (m == 1) {
    edges[0] = grid.row_position[0] - single_row_half_pitch;
    edges[1] = grid.row_position[0] + single_row_half_pitch;
    return edges;
  }
  for (int i = 1; i < m; ++i) {
    edges[static_cast<std::size_t>(i)] = 0.5 * (grid.row_position[i - 1] + grid.row_position[i]);
  }
  edges[0] = 2.0 * grid.row_position[0] - edges[1];
  edges[static_cast<std::size_t>(m)] =
      2.0 * grid.row_position[m - 1] - edges[static_cast<std::size_t>(m) - 1];
  return edges;
}

Eigen::Vector3d Mapped(const Eigen::Vector3d& p, double sign, double shift) {
  return {p.x(), sign * p.y() + shift, p.z()};
}

}  // namespace

RenderMesh RevolutionRenderMesh(const SurfaceGrid& grid, double axial_sign, double axial_shift) {
  CheckGrid(grid);
  const int m = grid.rows, n = grid.columns;
  std::vector<double> radius(static_cast<std::size_t>(m));
  for (int i = 0; i < m; ++i) {
    const Eigen::Vector3d c = grid.centre.col(grid.index(i, 0));
    radius[static_cast<std::size_t>(i)] = std::hypot(c.x(), c.z());
  }
  // A single row has no pitch to read; a cell as long as it is wide keeps the picture readable.
  const std::vector<double> edges = RowEdges(grid, M_PI * radius[0] / n);
  auto radius_at = [&](double y) {
    if (m == 1) return radius[0];
    // Linear through the two nearest row centres (extrapolated at the ends).
    int k = 0;
    while (k < m - 2 && y > grid.row_position[k + 1]) ++k;
    const double y0 = grid.row_position[k], y1 = grid.row_position[k + 1];
    const double t = (y - y0) / (y1 - y0);
    return (1.0 - t) * radius[static_cast<std::size_t>(k)] +
           t * radius[static_cast<std::size_t>(k) + 1];
  };
  const double half = M_PI / n;
  RenderMesh mesh;
  mesh.corners.reserve(4 * static_cast<std::size_t>(grid.size()));
  mesh.directions.reserve(static_cast<std::size_t>(grid.size()));
  for (int i = 0; i < m; ++i) {
    const double ya = edges[static_cast<std::size_t>(i)];
    const double yb = edges[static_cast<std::size_t>(i) + 1];
    const double ra = std::max(radius_at(ya), 0.0), rb = std::max(radius_at(yb), 0.0);
    for (int j = 0; j < n; ++j) {
      const double a0 = grid.column_angle[j] - half, a1 = grid.column_angle[j] + half;
      const auto point = [&](double r, double y, double a) {
        return Mapped(Eigen::Vector3d(r * std::cos(a), y, r * std::sin(a)), axial_sign,
                      axial_shift);
      };
      mesh.corners.push_back(point(ra, ya, a0));
      mesh.corners.push_back(point(rb, yb, a0));
      mesh.corners.push_back(point(rb, yb, a1));
      mesh.corners.push_back(point(ra, ya, a1));
      Eigen::Vector3d d = grid.normal.col(grid.index(i, j));
      d.y() *= axial_sign;
      mesh.directions.push_back(d);
    }
  }
  return mesh;
}

RenderMesh FlatCellRenderMesh(const SurfaceGrid& grid, double cell_width, double axial_sign,
                              double axial_shift) {
  CheckGrid(grid);
  if (!(cell_width > 0.0) || !std::isfinite(cell_width)) {
    throw UserError("render mesh: cell width must be positive");
  }
  const std::vector<double> edges = RowEdges(grid, 0.5 * cell_width);
  RenderMesh mesh;
  mesh.corners.reserve(4 * static_cast<std::size_t>(grid.size()));
  mesh.directions.reserve(static_cast<std::size_t>(grid.size()));
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitY();
  for (int i = 0; i < grid.rows; ++i) {
    const double ya = edges[static_cast<std::size_t>(i)];
    const double yb = edges[static_cast<std::size_t>(i) + 1];
    for (int j = 0; j < grid.columns; ++j) {
      const int k = grid.index(i, j);
      const Eigen::Vector3d normal = grid.normal.col(k);
      const Eigen::Vector3d across = 0.5 * cell_width * axis.cross(normal).normalized();
      Eigen::Vector3d c = grid.centre.col(k);
      const auto point = [&](double y, double side) {
        Eigen::Vector3d p = c + side * across;
        p.y() = y;
        return Mapped(p, axial_sign, axial_shift);
      };
      mesh.corners.push_back(point(ya, -1.0));
      mesh.corners.push_back(point(yb, -1.0));
      mesh.corners.push_back(point(yb, 1.0));
      mesh.corners.push_back(point(ya, 1.0));
      Eigen::Vector3d d = normal;
      d.y() *= axial_sign;
      mesh.directions.push_back(d);
    }
  }
  return mesh;
}

}  // namespace fitfeel
