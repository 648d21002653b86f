#include "surfaces/cylindrical/cylindrical_generator.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "surfaces/cylindrical/cylindrical_discretizer.h"
#include "surfaces/cylindrical/cylindrical_form_wavelengths.h"
#include "surfaces/cylindrical/elastic_options.h"
#include "surfaces/cylindrical/process_model.h"
#include "surfaces/cylindrical/random_draws.h"
#include "surfaces/cylindrical/sms_conformance.h"

namespace fitfeel::cylindrical {
namespace {

constexpr double kPi = std::numbers::pi;
// A capable process scraps a few parts per million; this many in a row means it cannot make one.
constexpr int kMaxSizeRedraws = 100000;

// Paper Fig. 3: the sampling sections of one form wave. Its wavelength is drawn in
// (10 mm, l) (eq. 3's companion rule); the sections sit at its peaks and troughs, every half wave
// from a random phase, each snapped to the row that contains it. The two end rows are sampling
// sections too: the wave goes on past the ends of the surface, so the profile there is a value of
// it like any other. A surface shorter than 10 mm holds at most half a form wave: only its ends.
std::vector<int> SamplingRows(const SurfaceGrid& g, double length, Rng& rng) {
  const double lambda =
      length > kMinFormWavelength ? Uniform(rng, kMinFormWavelength, length) : 2.0 * length;
  const double half = lambda / 2.0;
  const double pitch = length / g.rows;
  std::vector<int> rows = {0, g.rows - 1};
  for (double y = Uniform(rng, 0.0, half); y < length; y += half) {
    rows.push_back(std::clamp(static_cast<int>(std::floor(y / pitch)), 0, g.rows - 1));
  }
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows;
}

// Values at every row from values at the sampling rows (one column per sampling row), by
// half-cosine interpolation: each stretch between a peak and the next trough is half a cosine
// wave, as the paper's form wave is, and every interpolated value is a convex combination of its
// two neighbours, so no interpolated section exceeds the sampled ones' limits.
Eigen::MatrixXd Interpolate(const SurfaceGrid& g, const std::vector<int>& rows,
                            const Eigen::MatrixXd& values) {
  Eigen::MatrixXd out(values.rows(), g.rows);
  size_t k = 0;
  for (int i = 0; i < g.rows; ++i) {
    while (k + 1 < rows.size() && rows[k + 1] <= i) ++k;
    if (k + 1 >= rows.size() || rows[k] == i) {
      out.col(i) = values.col(k);
      continue;
    }
    const double t = (g.row_position(i) - g.row_position(rows[k])) /
                     (g.row_position(rows[k + 1]) - g.row_position(rows[k]));
    const double w = (1.0 - std::cos(kPi * t)) / 2.0;
    out.col(i) = (1.0 - w) * values.col(k) + w * values.col(k + 1);
  }
  return out;
}

// Axis straightness, eqs. 3-4: at each sampling section the axis is displaced by e in direction
// alpha, alpha ~ U(0, 2 pi), e ~ U(0, t/2); the displacement vector is interpolated between
// sections, and V = e cos(alpha - beta_j). Every section centre stays within t/2 of the nominal
// axis (eq. 5), so the axis lies in a cylinder of diameter t.
Eigen::VectorXd AxisComponent(const SurfaceGrid& g, double length, double t, Rng& rng) {
  const std::vector<int> rows = SamplingRows(g, length, rng);
  Eigen::MatrixXd centres(2, rows.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    const double alpha = Uniform(rng, 0.0, 2.0 * kPi);
    const double e = Uniform(rng, 0.0, t / 2.0);
    centres.col(k) << e * std::cos(alpha), e * std::sin(alpha);
  }
  const Eigen::MatrixXd c = Interpolate(g, rows, centres);
  // The columns' directions once, not once per row.
  Eigen::VectorXd cs(g.columns), sn(g.columns);
  for (int j = 0; j < g.columns; ++j) {
    cs(j) = std::cos(g.column_angle(j));
    sn(j) = std::sin(g.column_angle(j));
  }
  Eigen::VectorXd v(g.size());
  for (int i = 0; i < g.rows; ++i)
    for (int j = 0; j < g.columns; ++j) v(g.index(i, j)) = c(0, i) * cs(j) + c(1, i) * sn(j);
  return v;
}

// Generatrix straightness: an axisymmetric wave of the radius along the axis (barrel, hourglass,
// waviness of the diameter), alternating peaks and troughs of height U(0, t/2) on either side of
// the nominal radius, so each generatrix alone stays within a zone of width t.
Eigen::VectorXd GeneratrixComponent(const SurfaceGrid& g, double length, double t, Rng& rng) {
  const std::vector<int> rows = SamplingRows(g, length, rng);
  Eigen::MatrixXd values(1, rows.size());
  const double first = Uniform(rng) < 0.5 ? 1.0 : -1.0;
  for (size_t k = 0; k < rows.size(); ++k) {
    values(0, k) = (k % 2 == 0 ? first : -first) * Uniform(rng, 0.0, t / 2.0);
  }
  const Eigen::MatrixXd r = Interpolate(g, rows, values);
  Eigen::VectorXd v(g.size());
  for (int i = 0; i < g.rows; ++i) v.segment(i * g.columns, g.columns).setConstant(r(0, i));
  return v;
}

// Roundness: at each sampling section, 1 to 3 distinct random lobing harmonics k in [2, K]
// (K = MaxRoundnessHarmonic(d), and at most n/4 so that each lobe has 4 or more cells) with
// random amplitudes and phases, scaled so that the section's peak-to-valley about the nominal
// centre is a drawn U(0, t): its minimum-zone roundness is then at most that. Harmonics k >= 2 do
// not move the section centre (no axis change) and leave the mean radius (the size) alone.
Eigen::VectorXd RoundnessComponent(const SurfaceGrid& g, double diameter, double length, double t,
                                   Rng& rng) {
  const int K = std::min(MaxRoundnessHarmonic(diameter), g.columns / 4);
  if (K < 2) return Eigen::VectorXd::Zero(g.size());
  const std::vector<int> rows = SamplingRows(g, length, rng);
  Eigen::MatrixXd profiles = Eigen::MatrixXd::Zero(g.columns, rows.size());
  std::vector<int> harmonics;
  for (size_t s = 0; s < rows.size(); ++s) {
    harmonics.clear();
    for (int k = 2; k <= K; ++k) harmonics.push_back(k);
    const int count = std::min<int>(1 + static_cast<int>(3.0 * Uniform(rng)), harmonics.size());
    for (int h = 0; h < count; ++h) {
      // Partial Fisher-Yates: harmonics[h] becomes a random one of the remaining.
      const int pick = h + static_cast<int>(Uniform(rng) * (harmonics.size() - h));
      std::swap(harmonics[h], harmonics[pick]);
      const double amplitude = Uniform(rng);
      const double phase = Uniform(rng, 0.0, 2.0 * kPi);
      for (int j = 0; j < g.columns; ++j) {
        profiles(j, s) += amplitude * std::cos(harmonics[h] * g.column_angle(j) + phase);
      }
    }
    const double pv = profiles.col(s).maxCoeff() - profiles.col(s).minCoeff();
    const double target = Uniform(rng, 0.0, t);
    profiles.col(s) *= pv > 0.0 ? target / pv : 0.0;
  }
  const Eigen::MatrixXd r = Interpolate(g, rows, profiles);  // columns x rows
  Eigen::VectorXd v(g.size());
  for (int i = 0; i < g.rows; ++i) v.segment(i * g.columns, g.columns) = r.col(i);
  return v;
}

// Waviness as geometry (texture: din7190): wavelengths between 1 and 10 mm (ISO 21920-3's default
// waviness band, between the roughness cut-off 0.8 mm and the form's 10 mm), no shorter than four
// cells of the grid. Two circumferential waves (orders k with pi d / k in that band) and one axial
// wave, random phases and weights, scaled so that the whole peak-to-valley is the spec's waviness
// height A (the same reading of A as the paper's band +-(A + Rz)/2). A grid too coarse for any
// wave in the band gets none in that direction.
Eigen::VectorXd WavinessComponent(const SurfaceGrid& g, double diameter, double length,
                                  double height, Rng& rng) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(g.size());
  const double circumference = kPi * diameter;
  const int k_lo = std::max(2, static_cast<int>(std::ceil(circumference / 10e-3)));
  const int k_hi = std::min(static_cast<int>(std::floor(circumference / 1e-3)), g.columns / 4);
  for (int w = 0; w < 2 && k_lo <= k_hi; ++w) {
    const int k = k_lo + static_cast<int>(Uniform(rng) * (k_hi - k_lo + 1));
    const double weight = Uniform(rng, 0.5, 1.0), phase = Uniform(rng, 0.0, 2.0 * kPi);
    // The wave's value per column once, added to every row.
    Eigen::VectorXd wave(g.columns);
    for (int j = 0; j < g.columns; ++j) wave(j) = weight * std::cos(k * g.column_angle(j) + phase);
    for (int i = 0; i < g.rows; ++i) {
      for (int j = 0; j < g.columns; ++j) v[g.index(i, j)] += wave(j);
    }
  }
  const double pitch = g.rows > 1 ? length / g.rows : length;
  const double lambda_lo = std::max(1e-3, 4.0 * pitch), lambda_hi = std::min(10e-3, length);
  if (lambda_lo <= lambda_hi) {
    const double lambda = Uniform(rng, lambda_lo, lambda_hi);
    const double weight = Uniform(rng, 0.5, 1.0), phase = Uniform(rng, 0.0, 2.0 * kPi);
    for (int i = 0; i < g.rows; ++i) {
      const double a = weight * std::cos(2.0 * kPi * g.row_position(i) / lambda + phase);
      for (int j = 0; j < g.columns; ++j) v[g.index(i, j)] += a;
    }
  }
  const double pv = v.size() > 0 ? v.maxCoeff() - v.minCoeff() : 0.0;
  return pv > 0.0 ? Eigen::VectorXd(v * (height / pv)) : v;
}

struct FormCheck {
  FormCharacteristic characteristic;
  double tolerance;
};

// True when `form` meets every check; then `widths` (when given) holds each check's zone width,
// in the order of `checks`.
bool MeetsForm(const std::vector<FormCheck>& checks, double radius, const SurfaceGrid& g,
               const Eigen::VectorXd& form, std::vector<double>* widths = nullptr) {
  if (widths != nullptr) widths->clear();
  if (checks.empty()) return true;
  const metrology::CylinderSamples s = metrology::SamplesFromGrid(radius, g, form);
  for (const auto& c : checks) {
    const double w = metrology::EvaluateCylinderForm(c.characteristic, s);
    if (w > c.tolerance) return false;
    if (widths != nullptr) widths->push_back(w);
  }
  return true;
}

// Largest k in [0, 1] with V_dimension + k F inside the size limits everywhere; `violating`
// counts the cells outside them at k = 1. Feasible at k = 0 whenever V_dimension is.
double FeasibleScale(const Eigen::VectorXd& vd, const Eigen::VectorXd& f, const SurfaceGrid& g,
                     SizeLimit mode, double lo, double up, int* violating) {
  double k = 1.0;
  *violating = 0;
  // 1e-18 m: floating-point rounding of sums of micrometre values, not a violation.
  constexpr double kRounding = 1e-18;
  auto limit = [&](double a, double b, double low, double high, int cells) {
    if (a + b > high + kRounding) {
      *violating += cells;
      if (b > 0.0) k = std::min(k, std::max(0.0, (high - a) / b));
    } else if (a + b < low - kRounding) {
      *violating += cells;
      if (b < 0.0) k = std::min(k, std::max(0.0, (low - a) / b));
    }
  };
  if (mode == SizeLimit::kTwoPoint) {
    const int half = g.columns / 2;
    for (int i = 0; i < g.rows; ++i)
      for (int j = 0; j < half; ++j) {
        const int p = g.index(i, j), q = g.index(i, j + half);
        limit(vd(p) + vd(q), f(p) + f(q), lo, up, 2);
      }
  } else {
    for (int c = 0; c < g.size(); ++c) limit(vd(c), f(c), lo / 2.0, up / 2.0, 1);
  }
  return k;
}

// The range of F's contribution to the constrained quantity (two-point: F_a + F_b over opposite
// pairs; radial: 2 F per cell, in diameter terms), for the per-part size draw.
std::pair<double, double> Spread(const Eigen::VectorXd& f, const SurfaceGrid& g, SizeLimit mode) {
  double a = std::numeric_limits<double>::infinity(), b = -a;
  if (mode == SizeLimit::kTwoPoint) {
    const int half = g.columns / 2;
    for (int i = 0; i < g.rows; ++i)
      for (int j = 0; j < half; ++j) {
        const double s = f(g.index(i, j)) + f(g.index(i, j + half));
        a = std::min(a, s);
        b = std::max(b, s);
      }
  } else {
    a = 2.0 * f.minCoeff();
    b = 2.0 * f.maxCoeff();
  }
  return {a, b};
}

}  // namespace

void CylindricalVariationGenerator::DoConfigure(const SurfaceOptions& options) {
  const CylindricalOptions& parsed = OptionsAs<CylindricalOptions>(options);
  options_.size_draw = parsed.size_draw;
  options_.size_limit = parsed.size_limit;
}

SkinModelShape CylindricalVariationGenerator::DoGenerate(const PartSpec& part,
                                                         const SurfaceGrid& grid,
                                                         TextureMode texture, Rng& rng) const {
  const CylindricalGeometry& geometry = AsCylinder(part);
  const double lo = part.size.lower_deviation, up = part.size.upper_deviation;
  if (!(lo <= up)) {
    throw UserError("part '" + part.name + "': lower size deviation exceeds the upper one");
  }
  if (grid.columns % 2 != 0) {
    throw UserError("part '" + part.name + "': the grid needs an even number of columns");
  }
  // Step 3's order: form first, characteristic by characteristic, each checked against every
  // specified form tolerance on the accumulated form.
  std::vector<FormCheck> checks;
  double t_axis = 0.0, t_gen = 0.0, t_round = 0.0, t_cyl = 0.0;
  for (const auto& [c, t] : part.form.tolerance) {
    if (!(t >= 0.0)) throw UserError("part '" + part.name + "': negative " + ToString(c));
    switch (c) {
      case FormCharacteristic::kAxisStraightness:
        t_axis = t;
        break;
      case FormCharacteristic::kGeneratrixStraightness:
        t_gen = t;
        break;
      case FormCharacteristic::kRoundness:
        t_round = t;
        break;
      case FormCharacteristic::kCylindricity:
        t_cyl = t;
        break;
      default:
        throw UnsupportedError("part '" + part.name + "': a cylindrical surface has no " +
                               ToString(c) + " tolerance");
    }
    checks.push_back({c, t});
  }
  // A component without its own tolerance but bounded by cylindricity (which covers axis,
  // generatrix and roundness deviations alike) is drawn with the cylindricity tolerance.
  const bool has_cyl = part.form.tolerance.count(FormCharacteristic::kCylindricity) > 0;
  auto budget = [&](FormCharacteristic c, double own) {
    return part.form.tolerance.count(c) > 0 ? own : (has_cyl ? t_cyl : 0.0);
  };
  const double radius = geometry.diameter() / 2.0;
  const double length = geometry.length();
  SkinModelShape sms;
  sms.grid = grid;
  Eigen::VectorXd form = Eigen::VectorXd::Zero(grid.size());
  // The zone widths of `form` as it stands, one per check (NaN: not measured yet), and its
  // samples once a width had to be measured: the check that accepted a component measured them
  // all, so the next component's budget and the process's scaling read them instead of
  // evaluating the same form again (a minimum-zone evaluation is most of a shape's drawing).
  constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> widths(checks.size(), kUnknown), trial_widths;
  std::optional<metrology::CylinderSamples> samples;
  auto integrate = [&](const std::function<Eigen::VectorXd()>& draw) {
    Eigen::VectorXd component;
    samples.reset();
    for (int attempt = 0; attempt <= options_.max_regenerations; ++attempt) {
      if (attempt > 0) ++sms.regenerations;
      component = draw();
      if (MeetsForm(checks, radius, grid, form + component, &trial_widths)) {
        form += component;
        widths.swap(trial_widths);
        return;
      }
    }
    std::fill(widths.begin(), widths.end(), kUnknown);
    // Last resort: scale the last draw back. Every zone width is a convex function of the data,
    // so the k that pass form an interval from 0 (where the accumulated form passed): bisection.
    double good = 0.0, bad = 1.0;
    for (int it = 0; it < 30; ++it) {
      const double mid = (good + bad) / 2.0;
      (MeetsForm(checks, radius, grid, form + mid * component) ? good : bad) = mid;
    }
    form += good * component;
  };
  // Each component is drawn within the tolerance left by those before it. Zone widths are
  // subadditive (w(F + C) <= w(F) + w(C)), and a component drawn with bound B contributes at most
  // B to every characteristic it touches (see the component functions), so drawing with
  // B <= t - w(F) for each touched, specified characteristic keeps the sum in tolerance; the check
  // and regeneration remain the guard for what the linear bounds do not see (e.g. the e^2/2R
  // curvature terms of a displaced circle).
  struct Touch {
    FormCharacteristic characteristic;
    double gain;  // the component adds at most gain * B to it
  };
  // The zone width of the current form for a specified characteristic (every one is checked).
  auto width_of = [&](FormCharacteristic c) {
    std::size_t k = 0;
    while (checks[k].characteristic != c) ++k;
    if (std::isnan(widths[k])) {
      if (!samples) samples = metrology::SamplesFromGrid(radius, grid, form);
      widths[k] = metrology::EvaluateCylinderForm(c, *samples);
    }
    return widths[k];
  };
  auto remaining = [&](double own, std::initializer_list<Touch> touched) {
    double bound = own;
    if (bound <= 0.0) return 0.0;
    const bool flat = form.cwiseAbs().maxCoeff() == 0.0;
    for (const Touch& touch : touched) {
      const auto it = part.form.tolerance.find(touch.characteristic);
      if (it == part.form.tolerance.end()) continue;
      const double used = flat ? 0.0 : width_of(touch.characteristic);
      bound = std::min(bound, (it->second - used) / touch.gain);
    }
    return std::max(bound, 0.0);
  };
  using FC = FormCharacteristic;
  // Axis bow: every V within +-B/2, so at most B on axis straightness, generatrices and
  // cylindricity.
  if (const double t =
          remaining(budget(FC::kAxisStraightness, t_axis), {{FC::kAxisStraightness, 1.0},
                                                            {FC::kGeneratrixStraightness, 1.0},
                                                            {FC::kCylindricity, 1.0}});
      t > 0.0) {
    integrate([&] { return AxisComponent(grid, length, t, rng); });
  }
  // Axisymmetric radius wave within +-B/2: generatrices and cylindricity, not axis or roundness.
  if (const double t = remaining(budget(FC::kGeneratrixStraightness, t_gen),
                                 {{FC::kGeneratrixStraightness, 1.0}, {FC::kCylindricity, 1.0}});
      t > 0.0) {
    integrate([&] { return GeneratrixComponent(grid, length, t, rng); });
  }
  // Lobing: peak-to-valley <= B per section about a zero mean, so values within +-B: at most B on
  // roundness, 2B on cylindricity and on generatrices (sections differ).
  if (const double t = remaining(
          budget(FC::kRoundness, t_round),
          {{FC::kRoundness, 1.0}, {FC::kGeneratrixStraightness, 2.0}, {FC::kCylindricity, 2.0}});
      t > 0.0) {
    integrate([&] { return RoundnessComponent(grid, geometry.diameter(), length, t, rng); });
  }
  // A statistical process uses a Rayleigh-drawn fraction of each form tolerance: the paper's form
  // draw, scaled so that its most used characteristic uses exactly its drawn fraction (zone widths
  // scale with the data, so every other characteristic stays within its own fraction).
  const ProcessSpec& process = part.process;
  if (process.kind == ProcessKind::kStatistical && form.cwiseAbs().maxCoeff() > 0.0) {
    double k = std::numeric_limits<double>::infinity();
    for (const auto& [c, t] : part.form.tolerance) {
      const double r = DrawFormUtilisation(process, rng, &sms.rejections);
      const double w = width_of(c);
      if (t > 0.0 && w > 0.0) k = std::min(k, r * t / w);
    }
    if (std::isfinite(k)) form *= k;
  }
  // Eq. 6: texture as a truncated Gaussian per cell, only when sampled. Limits +-(A + Rz)/2 at
  // 3 sigma (sigma = (A + Rz)/6), the same distribution the contact analysis uses in expected mode.
  Eigen::VectorXd surface = Eigen::VectorXd::Zero(grid.size());
  const double half_range = (part.texture.waviness + part.texture.rz) / 2.0;
  if (texture == TextureMode::kSampled && half_range > 0.0) {
    const double sigma = half_range / 3.0;
    for (int c = 0; c < grid.size(); ++c) {
      double x = 0.0;
      do x = sigma * Normal(rng);
      while (std::abs(x) > half_range);
      surface(c) = x;
    }
  }
  if (texture == TextureMode::kDin7190 && part.texture.waviness > 0.0) {
    surface = WavinessComponent(grid, geometry.diameter(), length, part.texture.waviness, rng);
  }
  // Eqs. 1-2: the dimensional variation (radial: half the diameter deviation).
  const Eigen::VectorXd local = form + surface;
  Eigen::VectorXd dimension(grid.size());
  if (process.kind == ProcessKind::kStatistical) {
    if (options_.size_draw != SizeDraw::kPerPart) {
      throw UserError("part '" + part.name +
                      "': process: statistical draws one actual size per part; "
                      "model.options.size_draw: per_cell is the paper's literal eq. 1");
    }
    // Normal actual size; a part whose local sizes leave the limits is scrap and drawn again.
    const auto [a, b] = Spread(local, grid, options_.size_limit);
    const NormalLaw law = SizeLaw(process, lo, up, part.role);
    double D = 0.0;
    if (up - lo >= b - a) {
      for (;;) {
        D = law.mean + law.sd * Normal(rng);
        if (lo <= D + a && D + b <= up) break;
        if (++sms.rejections > kMaxSizeRedraws) {
          throw UserError("part '" + part.name + "': the size process (Cp " +
                          std::to_string(process.cp) + ", Cpk " + std::to_string(process.cpk) +
                          ") rejects every part");
        }
      }
    } else {
      D = lo - (up - lo) / (b - a) * a;  // as the paper's branch: the clamp scales the form back
    }
    dimension.setConstant(D / 2.0);
  } else if (options_.size_draw == SizeDraw::kPerPart) {
    const auto [a, b] = Spread(local, grid, options_.size_limit);
    const double u = Uniform(rng);
    // The diameter deviation D must satisfy lo <= D + s <= up for every local contribution s in
    // [a, b]; if the form spreads wider than the tolerance, D takes the value that the final
    // clamp's scaled-back form fits exactly.
    double D = 0.0;
    if (up - lo >= b - a) {
      D = (lo - a) + u * ((up - b) - (lo - a));
    } else {
      const double k = (up - lo) / (b - a);
      D = lo - k * a;
    }
    dimension.setConstant(D / 2.0);
  } else {
    for (int c = 0; c < grid.size(); ++c) dimension(c) = Uniform(rng, lo / 2.0, up / 2.0);
  }
  // Step 3's final clamp: scale the form and texture back (uniformly, which keeps every form
  // characteristic within its tolerance since zone widths scale with the data) until every size
  // constraint holds.
  const double k =
      FeasibleScale(dimension, local, grid, options_.size_limit, lo, up, &sms.scaled_back_cells);
  sms.dimension_part = dimension;
  sms.form_part = k * form;
  sms.surface_part = k * surface;
  sms.variation = sms.dimension_part + sms.form_part + sms.surface_part;
  return sms;
}

}  // namespace fitfeel::cylindrical
