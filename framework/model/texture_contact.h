#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "framework/core/export.h"
#include "framework/model/gps_spec.h"

namespace fitfeel {

enum class TextureMode;  // variation_generator.h

// A normal distribution N(mean, sigma^2) truncated to [lower, upper].
struct TruncatedGaussian {
  double mean = 0.0;
  double sigma = 1.0;
  double lower = -3.0;
  double upper = 3.0;
};

// Closed forms of docs/oracles.md for X ~ TruncatedGaussian and a gap g. They are the
// expected interference of a rough contact whose height difference X meets a gap g (paper eq. 6):
// no special cases beyond g <= lower (all of X interferes) and g >= upper (none does).
FITFEEL_API double ExceedanceProbability(const TruncatedGaussian& x, double gap);  // P(X > g)
FITFEEL_API double ExpectedInterference(const TruncatedGaussian& x, double gap);   // E[(X-g)+]
FITFEEL_API double ExpectedSquaredInterference(const TruncatedGaussian& x,
                                               double gap);  // E[((X-g)+)^2]

// Texture of one surface (paper eq. 6): heights Gaussian, limited to +-(A/2 + Rz/2).
// sigma is not fixed by the paper; we put the limit at 3 sigma (sigma = (A + Rz)/6 per surface),
// the usual reading of a "limit" of a Gaussian process band (99.73 % inside).
FITFEEL_API TruncatedGaussian SurfaceTexture(const TextureSpec& texture);

// The equivalent rough-on-smooth contact of two textured surfaces (paper, after Greenwood and
// Tripp [30]): heights add, so the limit is the sum of the two limits (-(A+Rz), A+Rz) for equal
// surfaces, and, the two textures being independent, the variances add (sigma_eq^2 = s1^2 + s2^2).
// For equal surfaces the limit therefore sits at 3*sqrt(2) = 4.24 sigma_eq. Returns sigma = 0 when
// neither surface has texture.
FITFEEL_API TruncatedGaussian EquivalentTexture(const TextureSpec& a, const TextureSpec& b);

// Expected interference E[(X - g)+] of a texture as a lookup table, for prepare-time loops over
// millions of cells: linear interpolation on a uniform grid over [lower, upper], exact (X's mean
// minus g) below it and zero above it. With the default 4097 points the interpolation error is
// below 1e-6 sigma. A zero-sigma texture gives the sharp max(0, -g).
class FITFEEL_API ExpectedInterferenceTable {
 public:
  ExpectedInterferenceTable() = default;
  explicit ExpectedInterferenceTable(const TruncatedGaussian& texture, int points = 4097);

  bool sharp() const { return sharp_; }
  // Beyond [lower, upper] the expected interference is exact and simple: mean - g below, 0 above
  // (both 0 for a sharp contact).
  double lower() const { return lower_; }
  double upper() const { return upper_; }
  double mean() const { return mean_; }
  // Largest probability density of the height difference X (its second derivative in g), 1/m;
  // +inf for a sharp contact. Bounds the error of interpolating E[(X - g)+] linearly in g.
  double max_density() const { return max_density_; }
  // E[(X - g)+], or max(0, -g) for a sharp contact. Inline: prepare calls it once per cell and
  // step (that loop, calling into the library per cell, was a quarter of a paper-law prepare).
  double operator()(double gap) const noexcept {
    if (sharp_) return gap < 0.0 ? -gap : 0.0;
    if (gap >= upper_) return 0.0;
    if (gap <= lower_) return mean_ - gap;
    const double s = (gap - lower_) / step_;
    const auto last = values_.size() - 1;
    auto i = static_cast<std::size_t>(s);
    if (i >= last) i = last - 1;
    const double t = s - static_cast<double>(i);
    return values_[i] + t * (values_[i + 1] - values_[i]);
  }

 private:
  bool sharp_ = true;
  double lower_ = 0.0;
  double upper_ = 0.0;
  double mean_ = 0.0;
  double max_density_ = std::numeric_limits<double>::infinity();
  double step_ = 0.0;
  std::vector<double> values_;
};

// The texture of a contact whose cells each press with their own interference, under the model's
// texture mode: the expected interference of the two surfaces' equivalent texture (`expected`,
// paper eq. 6: contact starts smoothly before the nominal surfaces touch), or the sharp
// max(0, -gap) (`sampled`: the texture is drawn into V). `din7190` (waviness as geometry, DIN 7190
// smoothing) is the cylindrical surface's own: refused with a UserError.
FITFEEL_API ExpectedInterferenceTable ContactTexture(const TextureSpec& inner,
                                                     const TextureSpec& outer, TextureMode mode);

}  // namespace fitfeel
