#include "surfaces/spherical/spherical_generator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "surfaces/common/surface_of_revolution.h"
#include "surfaces/spherical/spherical_form.h"
#include "surfaces/spherical/spherical_geometry.h"

namespace fitfeel::spherical {
namespace {

// The paper's shortest form wavelength; shorter undulations are texture.
constexpr double kMinFormWavelength = 10e-3;
constexpr int kMinLobes = 2;
constexpr int kMaxLobes = 10;

using revolution::Uniform;

}  // namespace

SkinModelShape SphericalVariationGenerator::DoGenerate(const PartSpec& part,
                                                       const SurfaceGrid& grid, TextureMode texture,
                                                       Rng& rng) const {
  const SphericalGeometry& geometry = GeometryOf(part);
  const int m = grid.rows, n = grid.columns;
  SkinModelShape sms;
  const double size = revolution::StartWithSize(part, grid, rng, &sms);
  const double lower = part.size.lower_deviation, upper = part.size.upper_deviation;

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
  revolution::ScaleFormIntoTolerances(
      part.form,
      [&](FormCharacteristic characteristic, const Eigen::VectorXd& form) {
        return EvaluateSphereForm(characteristic, geometry, grid, form);
      },
      &sms.form_part);
  revolution::SampleTexture(part.texture, texture, rng, &sms.surface_part);

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
  revolution::FinishWithScaleBack(factor, &sms);
  return sms;
}

}  // namespace fitfeel::spherical
