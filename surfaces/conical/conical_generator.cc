#include "surfaces/conical/conical_generator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "surfaces/common/surface_of_revolution.h"
#include "surfaces/conical/conical_form.h"
#include "surfaces/conical/conical_geometry.h"

namespace fitfeel::conical {
namespace {

// The paper's shortest form wavelength: shorter undulations are waviness, i.e. texture.
constexpr double kMinFormWavelength = 10e-3;
constexpr int kMinLobes = 2;
constexpr int kMaxLobes = 10;

using revolution::Uniform;

// Sampling sections at spacing `spacing` covering [0, length] (first one at or before 0).
struct Sections {
  double first = 0.0;
  double spacing = 1.0;
  int count = 0;
  // Cosine interpolation weight of section s+1 at position y, and the index s.
  void Locate(double y, int* s, double* w) const {
    const double u = std::clamp((y - first) / spacing, 0.0, count - 1.0);
    *s = std::min(static_cast<int>(u), count - 2);
    const double f = u - *s;
    *w = 0.5 - 0.5 * std::cos(M_PI * f);
  }
};

}  // namespace

SkinModelShape ConicalVariationGenerator::DoGenerate(const PartSpec& part, const SurfaceGrid& grid,
                                                     TextureMode texture, Rng& rng) const {
  const ConicalGeometry& geometry = GeometryOf(part);
  const int m = grid.rows, n = grid.columns;
  SkinModelShape sms;
  const double size = revolution::StartWithSize(part, grid, rng, &sms);
  const double lower = part.size.lower_deviation, upper = part.size.upper_deviation;

  const double t_axis = part.form.Get(FormCharacteristic::kAxisStraightness);
  const double t_round = part.form.Get(FormCharacteristic::kRoundness);
  const double t_gen = part.form.Get(FormCharacteristic::kGeneratrixStraightness);
  const double length = geometry.length();
  const double lambda = Uniform(rng, kMinFormWavelength, std::max(kMinFormWavelength, length));
  Sections sections;
  sections.spacing = 0.5 * lambda;
  sections.first = -Uniform(rng, 0.0, sections.spacing);
  sections.count = static_cast<int>(std::ceil((length - sections.first) / sections.spacing)) + 1;
  sections.count = std::max(sections.count, 2);
  std::vector<Eigen::Vector2d> centre(sections.count), lobe(sections.count);
  std::vector<double> generatrix(sections.count);
  for (int s = 0; s < sections.count; ++s) {
    const double e = Uniform(rng, 0.0, 0.5 * t_axis);
    const double a = Uniform(rng, 0.0, 2.0 * M_PI);
    centre[s] = e * Eigen::Vector2d(std::cos(a), std::sin(a));
    const double amplitude = Uniform(rng, 0.0, 0.5 * t_round);
    const double phase = Uniform(rng, 0.0, 2.0 * M_PI);
    lobe[s] = amplitude * Eigen::Vector2d(std::cos(phase), std::sin(phase));
    generatrix[s] = Uniform(rng, -0.5 * t_gen, 0.5 * t_gen);
  }
  const int lobes = std::uniform_int_distribution<int>(kMinLobes, std::min(kMaxLobes, n / 4))(rng);
  if (t_axis > 0.0 || t_round > 0.0 || t_gen > 0.0) {
    for (int i = 0; i < m; ++i) {
      int s = 0;
      double w = 0.0;
      sections.Locate(grid.row_position(i), &s, &w);
      const Eigen::Vector2d c = (1.0 - w) * centre[s] + w * centre[s + 1];
      const Eigen::Vector2d l = (1.0 - w) * lobe[s] + w * lobe[s + 1];
      const double g = (1.0 - w) * generatrix[s] + w * generatrix[s + 1];
      for (int j = 0; j < n; ++j) {
        const double beta = grid.column_angle(j);
        sms.form_part(grid.index(i, j)) = c.x() * std::cos(beta) + c.y() * std::sin(beta) +
                                          l.x() * std::cos(lobes * beta) +
                                          l.y() * std::sin(lobes * beta) + g;
      }
    }
  }
  // Step 3: every specified form tolerance, evaluated as a metrologist would.
  revolution::ScaleFormIntoTolerances(
      part.form,
      [&](FormCharacteristic characteristic, const Eigen::VectorXd& form) {
        return EvaluateConeForm(characteristic, geometry, grid, form);
      },
      &sms.form_part);
  revolution::SampleTexture(part.texture, texture, rng, &sms.surface_part);

  // Final clamp on the two-point sizes: size + f(i,j) + f(i,j+n/2) in [lower, upper].
  const int half = n / 2;
  double factor = 1.0;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < half; ++j) {
      const int a = grid.index(i, j), b = grid.index(i, j + half);
      const double f =
          sms.form_part(a) + sms.form_part(b) + sms.surface_part(a) + sms.surface_part(b);
      const double limit = f > 0.0 ? upper - size : lower - size;
      if (f != 0.0 && size + f > upper) factor = std::min(factor, limit / f);
      if (f != 0.0 && size + f < lower) factor = std::min(factor, limit / f);
      if (size + f > upper || size + f < lower) sms.scaled_back_cells += 2;
    }
  }
  revolution::FinishWithScaleBack(factor, &sms);
  return sms;
}

}  // namespace fitfeel::conical
