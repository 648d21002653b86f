#include "tests/example_slide/example_slide_shape.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "framework/core/error.h"
#include "tests/example_slide/example_slide_geometry.h"

namespace fitfeel::example_slide {

SurfaceGrid SlideDiscretizer::DoDiscretize(const PartSpec& part,
                                           const Resolution& resolution) const {
  const SlideGeometry& g = SlideGeometryOf(part);
  int rows = 0, strips = 0;
  if (resolution.is_auto()) {
    rows = std::max(1, static_cast<int>(std::ceil(g.length() / kAutoRowLength - 1e-9)));
    strips = 1;
  } else {
    if (resolution.columns % 2 != 0) {
      throw UserError("part '" + part.name + "': resolution columns (" +
                      std::to_string(resolution.columns) + ") must be even, one half per flank");
    }
    rows = resolution.rows;
    strips = resolution.columns / 2;
  }
  SurfaceGrid grid;
  grid.rows = rows;
  grid.columns = 2 * strips;
  const double dy = g.length() / rows, dz = g.height() / strips;
  grid.row_position.resize(rows);
  for (int i = 0; i < rows; ++i) grid.row_position[i] = (i + 0.5) * dy;
  grid.column_angle.resize(grid.columns);
  grid.centre.resize(3, grid.size());
  grid.normal.resize(3, grid.size());
  grid.area.resize(grid.size());
  for (int j = 0; j < grid.columns; ++j) {
    const double side = j < strips ? 1.0 : -1.0;
    grid.column_angle[j] = side > 0.0 ? 0.0 : std::numbers::pi;
    const double z = ((j % strips) + 0.5) * dz - 0.5 * g.height();
    for (int i = 0; i < rows; ++i) {
      const int cell = grid.index(i, j);
      grid.centre.col(cell) << side * 0.5 * g.width(), grid.row_position[i], z;
      grid.normal.col(cell) << side, 0.0, 0.0;
      grid.area[cell] = dy * dz;
    }
  }
  return grid;
}

SkinModelShape SlideVariationGenerator::DoGenerate(const PartSpec& part, const SurfaceGrid& grid,
                                                   TextureMode, Rng& rng) const {
  // The only draw: from the scene's generator, so a seed gives the same shape bit for bit.
  std::uniform_real_distribution<double> size(part.size.lower_deviation, part.size.upper_deviation);
  const double deviation = size(rng);
  SkinModelShape sms;
  sms.grid = grid;
  sms.dimension_part = Eigen::VectorXd::Constant(grid.size(), 0.5 * deviation);
  sms.form_part = Eigen::VectorXd::Zero(grid.size());
  sms.surface_part = Eigen::VectorXd::Zero(grid.size());
  sms.variation = sms.dimension_part;
  return sms;
}

std::vector<CharacteristicCheck> EvaluateSlideCharacteristics(const PartSpec& part,
                                                              const SkinModelShape& sms) {
  const SurfaceGrid& grid = sms.grid;
  const double b = part.size.nominal;
  const int strips = grid.columns / 2;
  double smallest = std::numeric_limits<double>::infinity();
  double largest = -smallest;
  for (int i = 0; i < grid.rows; ++i) {
    for (int q = 0; q < strips; ++q) {
      const double size =
          b + sms.variation[grid.index(i, q)] + sms.variation[grid.index(i, strips + q)];
      smallest = std::min(smallest, size);
      largest = std::max(largest, size);
    }
  }
  const double lower = b + part.size.lower_deviation;
  const double upper = b + part.size.upper_deviation;
  return {{"two_point_size_min", smallest, lower, upper},
          {"two_point_size_max", largest, lower, upper}};
}

}  // namespace fitfeel::example_slide
