#include "framework/model/texture_contact.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "framework/core/error.h"
#include "framework/model/variation_generator.h"

namespace fitfeel {
namespace {

double Pdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi); }
double Cdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }

// Mass of the truncated interval; refuses degenerate distributions instead of dividing by zero.
double Mass(const TruncatedGaussian& x) {
  if (!(x.sigma > 0.0) || !(x.upper > x.lower)) {
    throw std::invalid_argument("truncated Gaussian needs sigma > 0 and upper > lower");
  }
  const double z = Cdf((x.upper - x.mean) / x.sigma) - Cdf((x.lower - x.mean) / x.sigma);
  if (!(z > 0.0)) throw std::invalid_argument("truncated Gaussian interval holds no mass");
  return z;
}

}  // namespace

double ExceedanceProbability(const TruncatedGaussian& x, double gap) {
  const double z = Mass(x);
  if (gap <= x.lower) return 1.0;
  if (gap >= x.upper) return 0.0;
  return (Cdf((x.upper - x.mean) / x.sigma) - Cdf((gap - x.mean) / x.sigma)) / z;
}

double ExpectedInterference(const TruncatedGaussian& x, double gap) {
  const double z = Mass(x);
  const double alpha = (x.lower - x.mean) / x.sigma;
  const double beta = (x.upper - x.mean) / x.sigma;
  if (gap >= x.upper) return 0.0;
  if (gap <= x.lower) return x.mean + x.sigma * (Pdf(alpha) - Pdf(beta)) / z - gap;
  const double gamma = (gap - x.mean) / x.sigma;
  const double dphi = Cdf(beta) - Cdf(gamma);
  const double c = x.mean - gap;
  return (x.sigma * (Pdf(gamma) - Pdf(beta)) + c * dphi) / z;
}

double ExpectedSquaredInterference(const TruncatedGaussian& x, double gap) {
  const double z = Mass(x);
  if (gap >= x.upper) return 0.0;
  // Below the interval every X interferes: E[(X-g)^2] = Var + (E[X]-g)^2, with the truncated
  // moments; evaluating the in-interval form at g = lower gives the same value plus nothing, so
  // shift it: E[(X-g)^2] = E[(X-a)^2] + 2(a-g)E[X-a] + (a-g)^2.
  const double g = std::max(gap, x.lower);
  const double beta = (x.upper - x.mean) / x.sigma;
  const double gamma = (g - x.mean) / x.sigma;
  const double dphi = Cdf(beta) - Cdf(gamma);
  const double c = x.mean - g;
  const double s = x.sigma;
  const double at_g = (s * s * (dphi + gamma * Pdf(gamma) - beta * Pdf(beta)) +
                       2.0 * s * c * (Pdf(gamma) - Pdf(beta)) + c * c * dphi) /
                      z;
  if (gap >= x.lower) return at_g;
  const double shift = x.lower - gap;
  const double first = ExpectedInterference(x, x.lower);  // E[X - a], all of X above a
  return at_g + 2.0 * shift * first + shift * shift;
}

TruncatedGaussian SurfaceTexture(const TextureSpec& texture) {
  const double limit = 0.5 * (texture.waviness + texture.rz);
  return TruncatedGaussian{0.0, limit / 3.0, -limit, limit};
}

TruncatedGaussian EquivalentTexture(const TextureSpec& a, const TextureSpec& b) {
  const TruncatedGaussian ta = SurfaceTexture(a);
  const TruncatedGaussian tb = SurfaceTexture(b);
  const double limit = ta.upper + tb.upper;
  return TruncatedGaussian{0.0, std::hypot(ta.sigma, tb.sigma), -limit, limit};
}

ExpectedInterferenceTable::ExpectedInterferenceTable(const TruncatedGaussian& texture, int points) {
  if (!(texture.sigma > 0.0)) return;  // sharp contact
  if (points < 2) throw std::invalid_argument("expected-interference table needs >= 2 points");
  sharp_ = false;
  lower_ = texture.lower;
  upper_ = texture.upper;
  mean_ = ExpectedInterference(texture, lower_) + lower_;  // E[X]
  step_ = (upper_ - lower_) / (points - 1);
  // The truncated Gaussian's density peaks at its mean when the mean is inside the limits, else
  // at the limit nearest to it.
  const double peak = std::clamp(texture.mean, lower_, upper_);
  const double z = (peak - texture.mean) / texture.sigma;
  const double mass = 0.5 * (std::erf((upper_ - texture.mean) / (texture.sigma * M_SQRT2)) -
                             std::erf((lower_ - texture.mean) / (texture.sigma * M_SQRT2)));
  max_density_ = std::exp(-0.5 * z * z) / (texture.sigma * std::sqrt(2.0 * M_PI) * mass);
  values_.resize(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i) {
    values_[static_cast<std::size_t>(i)] = ExpectedInterference(texture, lower_ + i * step_);
  }
  values_.back() = 0.0;
}

ExpectedInterferenceTable ContactTexture(const TextureSpec& inner, const TextureSpec& outer,
                                         TextureMode mode) {
  if (mode == TextureMode::kDin7190) {
    throw UserError("texture din7190 (waviness as geometry, DIN 7190 smoothing) is implemented by "
                    "the cylindrical surface only; use expected or sampled here");
  }
  return mode == TextureMode::kExpected
             ? ExpectedInterferenceTable(EquivalentTexture(inner, outer))
             : ExpectedInterferenceTable();
}

}  // namespace fitfeel
