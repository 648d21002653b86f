#include "framework/safety/force_limiter.h"

#include <algorithm>
#include <cmath>

#include "framework/core/demand.h"

namespace fitfeel {

void ForceLimiter::Configure(double peak_force, double continuous_force, double window) {
  FITFEEL_DEMAND(peak_force > 0.0 && continuous_force > 0.0 && window > 0.0);
  peak_ = peak_force;
  continuous_ = std::min(continuous_force, peak_force);
  window_ = window;
  mean_square_ = 0.0;
}

Eigen::Vector3d ForceLimiter::Apply(const Eigen::Vector3d& force, double dt,
                                    Flags* flags) noexcept {
  Flags local;
  const double step = (std::isfinite(dt) && dt > 0.0) ? dt : 0.0;
  // Fraction of the way the average moves towards this tick's |F|^2.
  const double a = -std::expm1(-step / window_);
  double allowed_sq = peak_ * peak_;
  const double norm_sq = force.squaredNorm();
  if (a > 0.0) {
    const double continuous_sq = continuous_ * continuous_;
    const double thermal_room = (continuous_sq - (1.0 - a) * mean_square_) / a;
    if (thermal_room < allowed_sq) {
      allowed_sq = std::max(0.0, thermal_room);
      if (norm_sq > allowed_sq) local.continuous = true;
    }
  }
  Eigen::Vector3d out = force;
  if (norm_sq > allowed_sq) {
    if (!local.continuous) local.peak = true;
    // The small shrink keeps |F| <= limit despite rounding in the scale.
    const double scale = allowed_sq > 0.0 ? std::sqrt(allowed_sq / norm_sq) * (1.0 - 1e-12) : 0.0;
    out = force * scale;
  }
  mean_square_ += a * (out.squaredNorm() - mean_square_);
  if (flags != nullptr) *flags = local;
  return out;
}

double ForceLimiter::thermal_rms() const { return std::sqrt(mean_square_); }

}  // namespace fitfeel
