#include "surfaces/conical/conical_generator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "surfaces/conical/conical_form.h"
#include "surfaces/conical/conical_geometry.h"

namespace fitfeel::conical {
namespace {

// The paper's shortest form wavelength: shorter undulations are waviness, i.e. texture.
constexpr double kMinFormWavelength = 10e-3;
constexpr int kMinLobes = 2;
constexpr int kMaxLobes = 10;
// Step 3 converges in one or two rounds (the evaluations are homogeneous of degree one up to
// e^2/R terms); the bound only guards against a bug.
constexpr int kMaxScaleRounds = 30;
// Scaling lands a hair inside the tolerance so that rounding cannot leave it a hair outside.
constexpr double kScaleMargin = 1.0 - 1e-9;

double Uniform(Rng& rng, double lo, double hi) {
  if (!(hi > lo)) return lo;
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

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

double TruncatedGaussian(Rng& rng, double sigma, double bound) {
  std::normal_distribution<double> normal(0.0, sigma);
  for (;;) {
    const double x = normal(rng);
    if (std::abs(x) <= bound) return x;
  }
}

}  // namespace

SkinModelShape ConicalVariationGenerator::DoGenerate(const PartSpec& part, const SurfaceGrid& grid,
                                                     TextureMode texture, Rng& rng) const {
  const ConicalGeometry& geometry = GeometryOf(part);
  const int m = grid.rows, n = grid.columns, cells = grid.size();
  SkinModelShape sms;
  sms.grid = grid;
  sms.dimension_part = Eigen::VectorXd::Zero(cells);
  sms.form_part = Eigen::VectorXd::Zero(cells);
  sms.surface_part = Eigen::VectorXd::Zero(cells);

  const double lower = part.size.lower_deviation, upper = part.size.upper_deviation;
  const double size = Uniform(rng, lower, upper);
  sms.dimension_part.setConstant(0.5 * size);

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
  for (int round = 0; round < kMaxScaleRounds; ++round) {
    double factor = 1.0;
    for (const auto& [characteristic, tolerance] : part.form.tolerance) {
      const double value = EvaluateConeForm(characteristic, geometry, grid, sms.form_part);
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
  if (factor < 1.0) {
    factor = std::max(0.0, factor * kScaleMargin);
    sms.form_part *= factor;
    sms.surface_part *= factor;
  }
  sms.variation = sms.dimension_part + sms.form_part + sms.surface_part;
  return sms;
}

}  // namespace fitfeel::conical
