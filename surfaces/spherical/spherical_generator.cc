#include "surfaces/spherical/spherical_generator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "surfaces/spherical/spherical_form.h"
#include "surfaces/spherical/spherical_geometry.h"

namespace fitfeel::spherical {
namespace {

// The paper's shortest form wavelength; shorter undulations are texture.
constexpr double kMinFormWavelength = 10e-3;
constexpr int kMinLobes = 2;
constexpr int kMaxLobes = 10;
constexpr int kMaxScaleRounds = 30;
// Scaling lands a hair inside the tolerance so that rounding cannot leave it a hair outside.
constexpr double kScaleMargin = 1.0 - 1e-9;

double Uniform(Rng& rng, double lo, double hi) {
  if (!(hi > lo)) return lo;
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

double TruncatedGaussian(Rng& rng, double sigma, double bound) {
  std::normal_distribution<double> normal(0.0, sigma);
  for (;;) {
    const double x = normal(rng);
    if (std::abs(x) <= bound) return x;
  }
}

}  // namespace

SkinModelShape SphericalVariationGenerator::DoGenerate(const PartSpec& part,
                                                       const SurfaceGrid& grid, TextureMode texture,
                                                       Rng& rng) const {
  const SphericalGeometry& geometry = GeometryOf(part);
  const int m = grid.rows, n = grid.columns, cells = grid.size();
  SkinModelShape sms;
  sms.grid = grid;
  sms.dimension_part = Eigen::VectorXd::Zero(cells);
  sms.form_part = Eigen::VectorXd::Zero(cells);
  sms.surface_part = Eigen::VectorXd::Zero(cells);

  const double lower = part.size.lower_deviation, upper = part.size.upper_deviation;
  const double size = Uniform(rng, lower, upper);
  sms.dimension_part.setConstant(0.5 * size);

  const double t_round = part.form.Get(FormCharacteristic::kRoundness);
  const double t_sphere = part.form.Get(FormCharacteristic::kSphericity);
  const bool has_round = part.form.tolerance.count(FormCharacteristic::kRoundness) > 0;
  const double t_lobes = has_round ? t_round : t_sphere;
  const double width = geometry.width();
  const double lambda = Uniform(rng, kMinFormWavelength, std::max(kMinFormWavelength, width));
  const double spacing = 0.5 * lambda;
  const double first = -0.5 * width - Uniform(rng, 0.0, spacing);
  const int count = std::max(2, static_cast<int>(std::ceil((0.5 * width - first) / spacing)) + 1);
  std::vector<Eigen::Vector2d> lobe(count);
  std::vector<double> meridian(count);
  for (int s = 0; s < count; ++s) {
    const double amplitude = Uniform(rng, 0.0, 0.5 * t_lobes);
    const double phase = Uniform(rng, 0.0, 2.0 * M_PI);
    lobe[s] = amplitude * Eigen::Vector2d(std::cos(phase), std::sin(phase));
    meridian[s] = Uniform(rng, -0.25 * t_sphere, 0.25 * t_sphere);
  }
  const int lobes = std::uniform_int_distribution<int>(kMinLobes, std::min(kMaxLobes, n / 4))(rng);
  if (t_lobes > 0.0 || t_sphere > 0.0) {
    for (int i = 0; i < m; ++i) {
      const double u = std::clamp((grid.row_position(i) - first) / spacing, 0.0, count - 1.0);
      const int s = std::min(static_cast<int>(u), count - 2);
      const double w = 0.5 - 0.5 * std::cos(M_PI * (u - s));
      const Eigen::Vector2d l = (1.0 - w) * lobe[s] + w * lobe[s + 1];
      const double g = (1.0 - w) * meridian[s] + w * meridian[s + 1];
      for (int j = 0; j < n; ++j) {
        const double beta = grid.column_angle(j);
        sms.form_part(grid.index(i, j)) =
            l.x() * std::cos(lobes * beta) + l.y() * std::sin(lobes * beta) + g;
      }
    }
  }
  // Step 3.
  for (int round = 0; round < kMaxScaleRounds; ++round) {
    double factor = 1.0;
    for (const auto& [characteristic, tolerance] : part.form.tolerance) {
      const double value = EvaluateSphereForm(characteristic, geometry, grid, sms.form_part);
      if (value > tolerance) factor = std::min(factor, kScaleMargin * tolerance / value);
    }
    if (factor >= 1.0) break;
    sms.form_part *= factor;
  }

  const double texture_range = 0.5 * (part.texture.waviness + part.texture.rz);
  if (texture == TextureMode::kSampled && texture_range > 0.0) {
    for (int k = 0; k < cells; ++k) {
      sms.surface_part(k) = TruncatedGaussian(rng, texture_range / 3.0, texture_range);
    }
  }

  // Final clamp on the two-point sizes through the centre.
  const int half = n / 2;
  double factor = 1.0;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = grid.index(i, j), b = grid.index(m - 1 - i, (j + half) % n);
      const double f =
          sms.form_part(a) + sms.form_part(b) + sms.surface_part(a) + sms.surface_part(b);
      if (f > 0.0 && size + f > upper) factor = std::min(factor, (upper - size) / f);
      if (f < 0.0 && size + f < lower) factor = std::min(factor, (lower - size) / f);
      if (size + f > upper || size + f < lower) ++sms.scaled_back_cells;
    }
  }
  if (factor < 1.0) {
    factor = std::max(0.0, factor * kScaleMargin);
    sms.form_part *= factor;
    sms.surface_part *= factor;
  }
  sms.variation = sms.dimension_part + sms.form_part + sms.surface_part;
  return sms;
}

}  // namespace fitfeel::spherical
