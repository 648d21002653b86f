#include "surfaces/thread/thread_shape.h"

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <Eigen/Core>

#include "framework/core/error.h"
#include "framework/core/least_norm.h"
#include "surfaces/thread/thread_geometry.h"

namespace fitfeel::thread {
namespace {

constexpr double kPi = std::numbers::pi;

// Turn angle and radius of every cell, read back from the grid (row, strip).
struct CellCoordinates {
  Eigen::VectorXd theta, radius;
};

double FlankSign(int column, int columns) { return column < columns / 2 ? 1.0 : -1.0; }

}  // namespace

GridShape HelicoidDiscretizer::DoShape(const PartSpec& part, const Resolution& resolution) const {
  const HelicoidGeometry& g = HelicoidGeometryOf(part);
  int rows = 0, strips = 0;
  if (resolution.is_auto()) {
    rows = std::max(1, static_cast<int>(std::ceil(g.turns() * kAutoRowsPerTurn - 1e-9)));
    strips = kAutoStripsPerFlank;
  } else {
    if (resolution.columns % 2 != 0) {
      throw UserError("part '" + part.name + "': resolution columns (" +
                      std::to_string(resolution.columns) + ") must be even, one half per flank");
    }
    rows = resolution.rows;
    strips = resolution.columns / 2;
  }
  return GridShape{rows, 2 * strips};
}

SurfaceGrid HelicoidDiscretizer::DoDiscretize(const PartSpec& part,
                                              const Resolution& resolution) const {
  const HelicoidGeometry& g = HelicoidGeometryOf(part);
  const GridShape shape = DoShape(part, resolution);
  const int rows = shape.rows;
  const int strips = shape.columns / 2;
  SurfaceGrid grid;
  grid.rows = rows;
  grid.columns = shape.columns;
  const int cells = grid.size();
  const double total = 2.0 * kPi * g.turns();
  const double dtheta = total / rows;
  const double r1 = g.inner_radius(), r2 = g.outer_radius(), rp = g.pitch_radius();
  const double dr = (r2 - r1) / strips;
  const double k = std::tan(g.half_angle());
  const double c = g.pitch() / (2.0 * kPi);
  grid.row_position.resize(rows);
  for (int i = 0; i < rows; ++i) grid.row_position[i] = c * (i + 0.5) * dtheta;
  grid.column_angle.resize(grid.columns);
  grid.centre.resize(3, cells);
  grid.normal.resize(3, cells);
  grid.area.resize(cells);
  for (int j = 0; j < grid.columns; ++j) {
    const double s = FlankSign(j, grid.columns);
    grid.column_angle[j] = s * (0.5 * kPi - g.half_angle());
    const int q = j % strips;
    const double lo = r1 + q * dr, hi = r1 + (q + 1) * dr;
    const double r = 0.5 * (lo + hi);
    const double strip_area = dtheta * (g.AreaPrimitive(hi) - g.AreaPrimitive(lo));
    for (int i = 0; i < rows; ++i) {
      const int cell = grid.index(i, j);
      const double theta = (i + 0.5) * dtheta;
      const double ct = std::cos(theta), st = std::sin(theta);
      const double y = c * theta + s * (0.25 * g.pitch() - k * (r - rp));
      // z = -r sin(theta): theta grows with a turn about +y, so the helix advancing along +y is
      // right-handed (ISO 68-1 threads are right-hand unless marked LH).
      grid.centre.col(cell) << r * ct, y, -r * st;
      // Gradient of s (y - c theta - s P/4) + k (r - rp): k r_hat + s y_hat - s (c / r) t_hat,
      // t_hat = d(r_hat)/d(theta).
      const Eigen::Vector3d radial(ct, 0.0, -st), tangential(-st, 0.0, -ct);
      const Eigen::Vector3d n =
          k * radial + Eigen::Vector3d(0.0, s, 0.0) - s * (c / r) * tangential;
      grid.normal.col(cell) = n.normalized();
      grid.area[cell] = strip_area;
    }
  }
  return grid;
}

RenderMesh HelicoidRenderMesh(const PartSpec& part, const SurfaceGrid& grid) {
  const HelicoidGeometry& g = HelicoidGeometryOf(part);
  if (grid.rows < 1 || grid.columns < 2 || grid.columns % 2 != 0) {
    throw UserError("part '" + part.name + "': render mesh of a helicoid needs a two-flank grid, " +
                    "found " + std::to_string(grid.rows) + " x " + std::to_string(grid.columns));
  }
  const int strips = grid.columns / 2;
  const double total = 2.0 * kPi * g.turns();
  const double dtheta = total / grid.rows;
  // The bolt's grid slid back along its helix by its whole length, as the analyzer takes it.
  const double start = part.role == Role::kInner ? -total : 0.0;
  const double r1 = g.inner_radius(), rp = g.pitch_radius();
  const double dr = (g.outer_radius() - r1) / strips;
  const double k = std::tan(g.half_angle());
  const double c = g.pitch() / (2.0 * kPi);
  const auto cells = static_cast<std::size_t>(grid.size());
  RenderMesh mesh;
  mesh.corners.resize(4 * cells);
  mesh.directions.resize(cells);
  for (int i = 0; i < grid.rows; ++i) {
    const double lo_theta = start + i * dtheta;
    for (int j = 0; j < grid.columns; ++j) {
      const double s = FlankSign(j, grid.columns);
      const double lo_r = r1 + (j % strips) * dr;
      auto point = [&](double theta, double r) {
        return Eigen::Vector3d(r * std::cos(theta),
                               c * theta + s * (0.25 * g.pitch() - k * (r - rp)),
                               -r * std::sin(theta));
      };
      const auto cell = static_cast<std::size_t>(grid.index(i, j));
      const double hi_theta = lo_theta + dtheta, hi_r = lo_r + dr;
      mesh.corners[4 * cell] = point(lo_theta, lo_r);
      mesh.corners[4 * cell + 1] = point(lo_theta, hi_r);
      mesh.corners[4 * cell + 2] = point(hi_theta, hi_r);
      mesh.corners[4 * cell + 3] = point(hi_theta, lo_r);
      // The grid's normal turned with the slide along the helix (a turn by `start` about +y).
      const Eigen::Vector3d n = grid.normal.col(grid.index(i, j));
      const double cs = std::cos(start), sn = std::sin(start);
      mesh.directions[cell] =
          Eigen::Vector3d(cs * n.x() + sn * n.z(), n.y(), -sn * n.x() + cs * n.z());
    }
  }
  return mesh;
}

SkinModelShape HelicoidVariationGenerator::DoGenerate(const PartSpec& part, const SurfaceGrid& grid,
                                                      TextureMode, Rng& rng) const {
  const HelicoidGeometry& g = HelicoidGeometryOf(part);
  if (grid.columns % 2 != 0) throw UserError("part '" + part.name + "': not a two-flank grid");
  auto uniform = [&](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  const double beta = g.half_angle();
  const double d2_deviation = uniform(part.size.lower_deviation, part.size.upper_deviation);
  const double pitch_error = part.form.Declared("pitch_error");
  const double angle_error = part.form.Declared("flank_angle_error");
  const double pitch_deviation = uniform(-pitch_error, pitch_error);
  const double flank_a = uniform(-angle_error, angle_error);
  const double flank_b = uniform(-angle_error, angle_error);
  const double c = g.pitch() / (2.0 * kPi);
  const double rp = g.pitch_radius();

  SkinModelShape sms;
  sms.grid = grid;
  const int cells = grid.size();
  sms.dimension_part = Eigen::VectorXd::Constant(cells, 0.5 * d2_deviation * std::sin(beta));
  sms.form_part = Eigen::VectorXd::Zero(cells);
  sms.surface_part = Eigen::VectorXd::Zero(cells);
  for (int j = 0; j < grid.columns; ++j) {
    const double s = FlankSign(j, grid.columns);
    const double turn = s > 0.0 ? flank_a : flank_b;
    const double tilt = -(std::tan(beta + turn) - std::tan(beta)) * std::cos(beta);
    for (int i = 0; i < grid.rows; ++i) {
      const int cell = grid.index(i, j);
      const double theta = grid.row_position[i] / c;
      const double r = std::hypot(grid.centre(0, cell), grid.centre(2, cell));
      // Axial shift of the helix by the accumulated pitch deviation, seen along the flank normal.
      const double axial = pitch_deviation * theta / (2.0 * kPi);
      sms.form_part[cell] = s * axial * std::cos(beta) + tilt * (r - rp);
    }
  }
  sms.variation = sms.dimension_part + sms.form_part + sms.surface_part;
  return sms;
}

std::vector<CharacteristicCheck> EvaluateHelicoidCharacteristics(const PartSpec& part,
                                                                 const SkinModelShape& sms) {
  const HelicoidGeometry& g = HelicoidGeometryOf(part);
  const SurfaceGrid& grid = sms.grid;
  const double beta = g.half_angle();
  const double c = g.pitch() / (2.0 * kPi);
  const double rp = g.pitch_radius();
  const int half = grid.columns / 2;
  double constant[2], slope_theta[2], slope_r[2];
  for (int f = 0; f < 2; ++f) {
    const int n = grid.rows * half;
    Eigen::MatrixXd a(n, 3);
    Eigen::VectorXd v(n);
    int row = 0;
    for (int i = 0; i < grid.rows; ++i) {
      for (int q = 0; q < half; ++q) {
        const int cell = grid.index(i, f * half + q);
        const double r = std::hypot(grid.centre(0, cell), grid.centre(2, cell));
        a.row(row) << 1.0, grid.row_position[i] / c, r - rp;
        v[row] = sms.variation[cell];
        ++row;
      }
    }
    // With one row or one strip a coefficient is not observable: least norm.
    const Eigen::Vector3d x = LeastNormSolve(a, v);
    constant[f] = x[0];
    slope_theta[f] = x[1];
    slope_r[f] = x[2];
  }
  const double d2 = 2.0 * rp;
  const double d2_actual = d2 + (constant[0] + constant[1]) / std::sin(beta);
  const double pitch_deviation =
      0.5 * (slope_theta[0] - slope_theta[1]) * 2.0 * kPi / std::cos(beta);
  // A flank's half-angle deviation is reported, like every characteristic, as a length: the
  // normal deviation it causes across the flank's height (r1 to r2), a monotone function of the
  // angle, against the same function of the limits.
  const double height = g.outer_radius() - g.inner_radius();
  auto across_flank = [&](double turn) {
    return -(std::tan(beta + turn) - std::tan(beta)) * std::cos(beta) * height;
  };
  const double e = part.form.Declared("flank_angle_error");
  const double pitch_error = part.form.Declared("pitch_error");
  return {
      {"pitch_diameter", d2_actual, d2 + part.size.lower_deviation, d2 + part.size.upper_deviation},
      {"pitch_deviation", pitch_deviation, -pitch_error, pitch_error},
      {"flank_angle_deviation_a", slope_r[0] * height, across_flank(e), across_flank(-e)},
      {"flank_angle_deviation_b", slope_r[1] * height, across_flank(e), across_flank(-e)},
  };
}

}  // namespace fitfeel::thread
