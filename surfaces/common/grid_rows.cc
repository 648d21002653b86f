#include "surfaces/common/grid_rows.h"

#include <cstddef>

#include "framework/core/error.h"

namespace fitfeel {

std::vector<double> RowEdges(const PartSpec& part, const SurfaceGrid& grid) {
  const int m = grid.rows;
  const Eigen::VectorXd& c = grid.row_position;
  if (c.size() != m || m < 1) {
    throw UserError("part '" + part.name + "': grid row positions do not match its row count");
  }
  std::vector<double> e(static_cast<std::size_t>(m) + 1);
  if (m == 1) {
    const double l = part.geometry ? part.geometry->mating_length() : 0.0;
    if (!(l > 0.0)) {
      throw UserError("part '" + part.name + "': a one-row grid needs the part's mating length");
    }
    e[0] = c[0] - l / 2;
    e[1] = c[0] + l / 2;
  } else {
    for (int i = 1; i < m; ++i) {
      if (!(c[i] > c[i - 1])) {
        throw UserError("part '" + part.name + "': grid rows must be in increasing axial order");
      }
      e[static_cast<std::size_t>(i)] = 0.5 * (c[i - 1] + c[i]);
    }
    e[0] = c[0] - 0.5 * (c[1] - c[0]);
    e[static_cast<std::size_t>(m)] = c[m - 1] + 0.5 * (c[m - 1] - c[m - 2]);
  }
  const double first = e[0];
  for (double& x : e) x -= first;
  return e;
}

}  // namespace fitfeel
