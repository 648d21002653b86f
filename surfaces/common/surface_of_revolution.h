#pragma once

// Pieces every surface-of-revolution plugin (cone, sphere) builds its discretizer, variation
// generator and characteristic checks from: a grid of rows along the axis by equal angular
// columns, the seeded draws and the tolerance scaling of the paper's steps 1-3, and two-point
// sizes. Header-only and inline, so that a plugin links nothing more and exports nothing more.
// Each step draws from the generator in the order the plugins always did, so a seed keeps its
// skin model shape.

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framework/core/error.h"
#include "framework/core/number_text.h"
#include "framework/model/discretizer.h"
#include "framework/model/gps_spec.h"
#include "framework/model/skin_model_shape.h"
#include "framework/model/surface_type.h"
#include "framework/model/variation_generator.h"

namespace fitfeel::revolution {

using fitfeel::GridShape;

// The automatic resolution of a surface of revolution: `auto_columns` columns and one row per
// `auto_row_pitch` of the axial extent, clamped to [min_auto_rows, max_auto_rows].
struct AutoResolution {
  int columns = 72;
  double row_pitch = 0.0;
  int min_rows = 8;
  int max_rows = 400;
};

// `resolution`, or the automatic one over `extent`, checked: two-point sizes pair opposite columns
// and a minimum-zone circle needs four points on each side (an even count >= 8), and the surface
// (`noun`, e.g. "a cone") needs at least `min_rows` rows.
inline GridShape CheckedGridShape(const PartSpec& part, const Resolution& resolution, double extent,
                                  const AutoResolution& automatic, const std::string& noun,
                                  int min_rows) {
  GridShape shape{resolution.rows, resolution.columns};
  if (resolution.is_auto()) {
    shape.rows = std::clamp(static_cast<int>(std::ceil(extent / automatic.row_pitch)),
                            automatic.min_rows, automatic.max_rows);
    shape.columns = automatic.columns;
  }
  if (shape.columns < 8 || shape.columns % 2 != 0) {
    throw UserError("part '" + part.name + "': " + noun +
                    " needs an even number of columns >= 8, not " + MessageNumber(shape.columns));
  }
  if (shape.rows < min_rows) {
    throw UserError("part '" + part.name + "': " + noun + " needs at least " +
                    MessageNumber(min_rows) + " rows, not " + MessageNumber(shape.rows));
  }
  return shape;
}

// A grid of `shape` with every array sized and the column angles 2 pi j / n; rows and cells are
// left for the plugin.
inline SurfaceGrid EmptyGrid(const GridShape& shape) {
  SurfaceGrid grid;
  grid.rows = shape.rows;
  grid.columns = shape.columns;
  grid.row_position.resize(shape.rows);
  grid.column_angle.resize(shape.columns);
  grid.centre.resize(3, shape.rows * shape.columns);
  grid.normal.resize(3, shape.rows * shape.columns);
  grid.area.resize(shape.rows * shape.columns);
  for (int j = 0; j < shape.columns; ++j) grid.column_angle(j) = 2.0 * M_PI * j / shape.columns;
  return grid;
}

// One row of a surface of revolution's grid: where it sits on the axis, how far its cell centres
// are from the axis, the area of each of its cells, and its cells' normal away from the material
// as a radial and an axial component over their common length (1 for unit components; a sphere
// gives its centre's components and its radius, so that the normal is exactly centre / radius).
struct RevolvedRow {
  double y = 0.0;       // m
  double radius = 0.0;  // m
  double area = 0.0;    // of each cell, m^2
  double normal_radial = 0.0;
  double normal_axial = 0.0;
  double normal_length = 1.0;
};

// The grid of `shape` whose row i is row(i): cell (i, j), at column angle beta_j, has its centre
// at (radius cos beta_j, y, radius sin beta_j) and the normal (normal_radial cos beta_j,
// normal_axial, normal_radial sin beta_j) / normal_length.
template <typename Row>
SurfaceGrid RevolvedGrid(const GridShape& shape, Row&& row) {
  SurfaceGrid grid = EmptyGrid(shape);
  for (int i = 0; i < shape.rows; ++i) {
    const RevolvedRow r = row(i);
    grid.row_position(i) = r.y;
    for (int j = 0; j < shape.columns; ++j) {
      const int k = grid.index(i, j);
      const double c = std::cos(grid.column_angle(j)), s = std::sin(grid.column_angle(j));
      grid.centre.col(k) << r.radius * c, r.y, r.radius * s;
      grid.normal.col(k) << r.normal_radial * c / r.normal_length, r.normal_axial / r.normal_length,
          r.normal_radial * s / r.normal_length;
      grid.area(k) = r.area;
    }
  }
  return grid;
}

// Refuses a pair whose grids differ in their column count: the contact pairs the two parts' cells
// column by column. `pair` names the parts ("taper pin and hole").
inline void CheckSharedColumns(const SurfaceGrid& inner, const SurfaceGrid& outer,
                               const std::string& pair) {
  if (inner.columns != outer.columns) {
    throw UserError(pair + " must share their column count (" + MessageNumber(inner.columns) +
                    " vs " + MessageNumber(outer.columns) + ")");
  }
}

// A uniform draw in [lo, hi); lo without a draw when the interval is empty.
inline double Uniform(Rng& rng, double lo, double hi) {
  if (!(hi > lo)) return lo;
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// A normal draw with deviation `sigma`, redrawn until within +-bound.
inline double TruncatedGaussian(Rng& rng, double sigma, double bound) {
  std::normal_distribution<double> normal(0.0, sigma);
  for (;;) {
    const double x = normal(rng);
    if (std::abs(x) <= bound) return x;
  }
}

// Step 1: a skin model shape on `grid` with zero form and texture and the size deviation drawn
// uniformly within the size tolerance, half of it on each cell (radial); returns that size.
inline double StartWithSize(const PartSpec& part, const SurfaceGrid& grid, Rng& rng,
                            SkinModelShape* sms) {
  const int cells = grid.size();
  sms->grid = grid;
  sms->dimension_part = Eigen::VectorXd::Zero(cells);
  sms->form_part = Eigen::VectorXd::Zero(cells);
  sms->surface_part = Eigen::VectorXd::Zero(cells);
  const double size = Uniform(rng, part.size.lower_deviation, part.size.upper_deviation);
  sms->dimension_part.setConstant(0.5 * size);
  return size;
}

// Scaling lands a hair inside the tolerance so that rounding cannot leave it a hair outside.
inline constexpr double kScaleMargin = 1.0 - 1e-9;

// Step 3: scales `form_part` down until every specified form tolerance holds, each evaluated as a
// metrologist would by `evaluate(characteristic, form_part)`. Converges in one or two rounds (the
// evaluations are homogeneous of degree one up to e^2/R terms); the bound only guards against a
// bug.
template <typename Evaluate>
void ScaleFormIntoTolerances(const FormSpec& form, const Evaluate& evaluate,
                             Eigen::VectorXd* form_part) {
  constexpr int kMaxScaleRounds = 30;
  for (int round = 0; round < kMaxScaleRounds; ++round) {
    double factor = 1.0;
    for (const auto& [characteristic, tolerance] : form.tolerance) {
      const double value = evaluate(characteristic, *form_part);
      if (value > tolerance) factor = std::min(factor, kScaleMargin * tolerance / value);
    }
    if (factor >= 1.0) break;
    *form_part *= factor;
  }
}

// The sampled texture: per cell a normal draw (sigma = range / 3) truncated to the texture range,
// half of waviness plus Rz; nothing when texture is not sampled.
inline void SampleTexture(const TextureSpec& spec, TextureMode texture, Rng& rng,
                          Eigen::VectorXd* surface_part) {
  const double texture_range = 0.5 * (spec.waviness + spec.rz);
  if (texture == TextureMode::kSampled && texture_range > 0.0) {
    for (int k = 0; k < surface_part->size(); ++k) {
      (*surface_part)(k) = TruncatedGaussian(rng, texture_range / 3.0, texture_range);
    }
  }
}

// The last step: scales form and texture back by `factor` (< 1 when a two-point size left the
// size tolerance, with the margin applied here) and sums the variation.
inline void FinishWithScaleBack(double factor, SkinModelShape* sms) {
  if (factor < 1.0) {
    factor = std::max(0.0, factor * kScaleMargin);
    sms->form_part *= factor;
    sms->surface_part *= factor;
  }
  sms->variation = sms->dimension_part + sms->form_part + sms->surface_part;
}

// Which cell a two-point size pairs with (j, i) besides the opposite column j + n/2: the same row
// (a cone or cylinder: a diameter across a section), or the mirrored row m-1-i (a sphere: a
// diameter through the centre).
enum class Antipode { kSameRow, kMirroredRow };

struct TwoPointRange {
  double min = 0.0;
  double max = 0.0;
};

// Smallest and largest two-point size deviation (ISO 14405-1 LP): V(cell) + V(antipode) over
// every pair. Needs an even column count.
inline TwoPointRange TwoPointSizes(const SurfaceGrid& grid, const Eigen::VectorXd& deviation,
                                   Antipode antipode) {
  if (grid.columns % 2 != 0)
    throw std::invalid_argument("two-point sizes need an even column count");
  const int half = grid.columns / 2;
  TwoPointRange range{std::numeric_limits<double>::infinity(),
                      -std::numeric_limits<double>::infinity()};
  // Through a section each pair stands once in j < n/2; through the centre every cell is visited
  // (the sum of two is the same either way round).
  const int visited = antipode == Antipode::kSameRow ? half : grid.columns;
  for (int i = 0; i < grid.rows; ++i) {
    const int row = antipode == Antipode::kSameRow ? i : grid.rows - 1 - i;
    for (int j = 0; j < visited; ++j) {
      const double size =
          deviation(grid.index(i, j)) + deviation(grid.index(row, (j + half) % grid.columns));
      range.min = std::min(range.min, size);
      range.max = std::max(range.max, size);
    }
  }
  return range;
}

// Every characteristic of `part`'s spec on a skin model shape: two-point size limits on the whole
// variation, each specified form tolerance (`evaluate(characteristic, deviation)`) on the
// variation without the sampled texture (ISO form evaluation filters out its short wavelengths).
template <typename Evaluate>
std::vector<CharacteristicCheck> EvaluateCharacteristics(const PartSpec& part,
                                                         const SkinModelShape& sms,
                                                         Antipode antipode,
                                                         const Evaluate& evaluate) {
  std::vector<CharacteristicCheck> checks;
  const TwoPointRange size = TwoPointSizes(sms.grid, sms.variation, antipode);
  checks.push_back(
      {"two_point_size_min", size.min, part.size.lower_deviation, part.size.upper_deviation});
  checks.push_back(
      {"two_point_size_max", size.max, part.size.lower_deviation, part.size.upper_deviation});
  const Eigen::VectorXd form = sms.surface_part.size() == sms.variation.size()
                                   ? Eigen::VectorXd(sms.variation - sms.surface_part)
                                   : sms.variation;
  for (const auto& [characteristic, tolerance] : part.form.tolerance) {
    checks.push_back({ToString(characteristic), evaluate(characteristic, form), 0.0, tolerance});
  }
  return checks;
}

}  // namespace fitfeel::revolution
