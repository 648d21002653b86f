#include "surfaces/planar/planar_generator.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "framework/core/error.h"
#include "surfaces/planar/planar_characteristics.h"
#include "surfaces/planar/planar_geometry.h"
#include "surfaces/planar/planar_discretizer.h"

namespace fitfeel::planar {
namespace {

// Below this a scale-back factor is applied with a margin so that rounding never leaves a value a
// hair above its tolerance.
constexpr double kScaleMargin = 1.0 - 1e-12;

double Uniform(Rng& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}

std::optional<double> Tolerance(const PartSpec& part, FormCharacteristic c) {
  auto it = part.form.tolerance.find(c);
  if (it == part.form.tolerance.end()) return std::nullopt;
  return it->second;
}

double Tightest(std::initializer_list<std::optional<double>> tolerances) {
  std::optional<double> best;
  for (const auto& t : tolerances) {
    if (t && (!best || *t < *best)) best = t;
  }
  return best.value_or(0.0);
}

// The sampled form wave of eq. 3 along y at the row positions: sampling sections every half
// wavelength (peaks and troughs alternate), magnitudes in (0, amplitude/2), linear in between.
std::vector<double> FormWave(const Eigen::VectorXd& rows, double length, double amplitude,
                             Rng& rng) {
  std::vector<double> wave(static_cast<std::size_t>(rows.size()), 0.0);
  if (amplitude <= 0.0) return wave;
  const double longest = std::max(length, PlanarVariationGenerator::kMinFormWavelength);
  const double lambda = Uniform(rng, PlanarVariationGenerator::kMinFormWavelength, longest);
  const double half = 0.5 * lambda;
  const double start = -Uniform(rng, 0.0, half);
  double sign = Uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
  std::vector<double> at, value;
  for (double y = start; at.empty() || at.back() < length; y += half) {
    at.push_back(y);
    value.push_back(sign * Uniform(rng, 0.0, 0.5 * amplitude));
    sign = -sign;
  }
  for (Eigen::Index i = 0; i < rows.size(); ++i) {
    const double y = rows[i];
    std::size_t k = 1;
    while (k + 1 < at.size() && at[k] < y) ++k;
    const double s = std::clamp((y - at[k - 1]) / (at[k] - at[k - 1]), 0.0, 1.0);
    wave[static_cast<std::size_t>(i)] = (1.0 - s) * value[k - 1] + s * value[k];
  }
  return wave;
}

double TruncatedNormal(Rng& rng, double sigma, double limit) {
  std::normal_distribution<double> normal(0.0, sigma);
  for (;;) {
    const double x = normal(rng);
    if (std::abs(x) <= limit) return x;
  }
}

struct FaceTolerances {
  std::optional<double> straightness, flatness;
};

// Worst ratio value / tolerance of the face's own form checks on `values` (<= 1 passes).
double FaceExcess(const SurfaceGrid& grid, const FaceLayout& layout, int face,
                  const Eigen::VectorXd& values, const FaceTolerances& t) {
  double worst = 0.0;
  auto ratio = [](double value, double tol) {
    if (tol > 0.0) return value / tol;
    return value > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  };
  if (t.straightness) {
    worst = std::max(worst, ratio(FaceStraightness(grid, layout, face, values), *t.straightness));
  }
  if (t.flatness) {
    worst = std::max(worst, ratio(FaceFlatness(grid, layout, face, values).width, *t.flatness));
  }
  return worst;
}

}  // namespace

SkinModelShape PlanarVariationGenerator::DoGenerate(const PartSpec& part, const SurfaceGrid& grid,
                                                    TextureMode texture, Rng& rng) const {
  const PlanarGeometry& geometry = PlanarGeometryOf(part);
  const FaceLayout layout = LayoutOf(grid);
  if (layout.faces != geometry.faces()) {
    throw UserError("part '" + part.name + "': its grid does not have the " +
                    (geometry.faces() == 2 ? "2" : "4") + " faces of its geometry");
  }
  const double ei = part.size.lower_deviation;
  const double es = part.size.upper_deviation;
  if (!(ei <= es)) throw UserError("part '" + part.name + "': size limits are inverted");

  const int cells = grid.size();
  SkinModelShape sms;
  sms.grid = grid;
  sms.dimension_part = Eigen::VectorXd::Zero(cells);
  sms.form_part = Eigen::VectorXd::Zero(cells);
  sms.surface_part = Eigen::VectorXd::Zero(cells);

  const FaceTolerances face_tol{Tolerance(part, FormCharacteristic::kStraightness),
                                Tolerance(part, FormCharacteristic::kFlatness)};
  const std::optional<double> parallelism = Tolerance(part, FormCharacteristic::kParallelism);
  const std::optional<double> axis = Tolerance(part, FormCharacteristic::kAxisStraightness);
  // The bow of the pair's median (axis straightness) moves both faces alike; each face's own form
  // gets what the face tolerances leave after it, so that a draw usually passes at once.
  const double bow_amplitude =
      axis ? std::min(*axis, Tightest({face_tol.straightness, face_tol.flatness, axis})) : 0.0;
  const double line_amplitude = std::max(
      0.0, Tightest({face_tol.straightness, face_tol.flatness, parallelism}) - bow_amplitude);
  const double twist_amplitude =
      std::max(0.0, ((face_tol.flatness || parallelism) ? Tightest({face_tol.flatness, parallelism})
                                                        : line_amplitude) -
                        bow_amplitude);
  const double band = 0.5 * (part.texture.waviness + part.texture.rz);
  const bool sample_texture = texture == TextureMode::kSampled && band > 0.0;

  const int strips = layout.columns_per_face;
  std::vector<double> across(static_cast<std::size_t>(strips));
  for (int q = 0; q < strips; ++q) {
    // -1 .. 1 across the face's height.
    across[static_cast<std::size_t>(q)] = 2.0 * (q + 0.5) / strips - 1.0;
  }
  auto cell = [&](int pair, int k, int i, int q) {
    return grid.index(i, (2 * pair + k) * strips + q);
  };

  // The pair's form and sampled texture: a bow of the median (+ on one face, - on the other: the
  // faces are normal to opposite directions), then each face's line wave and twist.
  auto draw_pair = [&](int pair) {
    const std::vector<double> bow =
        FormWave(grid.row_position, geometry.length(), bow_amplitude, rng);
    for (int k = 0; k < 2; ++k) {
      const double side = k == 0 ? 1.0 : -1.0;
      const std::vector<double> line =
          FormWave(grid.row_position, geometry.length(), line_amplitude, rng);
      const std::vector<double> twist =
          FormWave(grid.row_position, geometry.length(), twist_amplitude, rng);
      for (int i = 0; i < grid.rows; ++i) {
        const auto ii = static_cast<std::size_t>(i);
        for (int q = 0; q < strips; ++q) {
          const int c = cell(pair, k, i, q);
          sms.form_part[c] =
              side * bow[ii] + line[ii] + 0.5 * across[static_cast<std::size_t>(q)] * twist[ii];
          sms.surface_part[c] = sample_texture ? TruncatedNormal(rng, band / 3.0, band) : 0.0;
        }
      }
    }
  };
  auto scale_pair = [&](int pair, double factor) {
    for (int k = 0; k < 2; ++k) {
      for (int i = 0; i < grid.rows; ++i) {
        for (int q = 0; q < strips; ++q) {
          const int c = cell(pair, k, i, q);
          sms.form_part[c] *= factor;
          sms.surface_part[c] *= factor;
        }
      }
    }
  };
  // Worst value / tolerance over every form and orientation characteristic of the pair. Each is
  // homogeneous of degree one in the form (and texture) part, so one factor 1 / ratio brings all
  // of them within their tolerances at once.
  auto pair_ratio = [&](int pair) {
    const Eigen::VectorXd combined = sms.form_part + sms.surface_part;
    auto ratio = [](double value, double tol) {
      if (tol > 0.0) return value / tol;
      return value > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    };
    double worst = std::max(FaceExcess(grid, layout, 2 * pair, combined, face_tol),
                            FaceExcess(grid, layout, 2 * pair + 1, combined, face_tol));
    if (parallelism) {
      worst = std::max(worst, ratio(PairParallelism(grid, layout, pair, combined), *parallelism));
    }
    if (axis)
      worst = std::max(worst, ratio(PairAxisStraightness(grid, layout, pair, combined), *axis));
    return worst;
  };

  for (int pair = 0; pair < layout.faces / 2; ++pair) {
    // One actual size of the pair, half of its deviation on each face.
    const double half_deviation = 0.5 * Uniform(rng, ei, es);
    for (int k = 0; k < 2; ++k) {
      for (int i = 0; i < grid.rows; ++i) {
        for (int q = 0; q < strips; ++q) sms.dimension_part[cell(pair, k, i, q)] = half_deviation;
      }
    }
    // Step 3: regenerate, then scale back.
    for (int attempt = 0;; ++attempt) {
      draw_pair(pair);
      const double worst = pair_ratio(pair);
      if (worst <= 1.0) break;
      if (attempt + 1 >= kMaxRegenerations) {
        scale_pair(pair, std::isfinite(worst) ? kScaleMargin / worst : 0.0);
        break;
      }
      ++sms.regenerations;
    }
    // Final clamp into the half-size limits, one factor for the pair.
    double factor = 1.0;
    for (int k = 0; k < 2; ++k) {
      for (int i = 0; i < grid.rows; ++i) {
        for (int q = 0; q < strips; ++q) {
          const int c = cell(pair, k, i, q);
          const double d = sms.dimension_part[c];
          const double e = sms.form_part[c] + sms.surface_part[c];
          const double v = d + e;
          if (v > 0.5 * es || v < 0.5 * ei) ++sms.scaled_back_cells;
          if (e > 0.0) factor = std::min(factor, (0.5 * es - d) / e);
          if (e < 0.0) factor = std::min(factor, (0.5 * ei - d) / e);
        }
      }
    }
    if (factor < 1.0) scale_pair(pair, std::max(0.0, factor * kScaleMargin));
  }
  sms.variation = sms.dimension_part + sms.form_part + sms.surface_part;
  return sms;
}

}  // namespace fitfeel::planar
