#pragma once

#include <Eigen/Core>

#include "framework/core/export.h"

namespace fitfeel {

// Bounds the force sent to a device by its peak rating and, through a first-order thermal model,
// by its continuous rating. Motor heating follows the square of the current, hence of the force, so
// the model tracks an exponential moving average of |F|^2 with the window as time constant; a
// force that would push sqrt(average) above the continuous rating is cut to the largest that does
// not. Short bursts up to the peak rating pass; sustained force converges to the continuous rating.
class FITFEEL_API ForceLimiter {
 public:
  // Prepare-time. All arguments positive and finite (asserted by the caller's validation).
  void Configure(double peak_force, double continuous_force, double window);
  void Reset() noexcept { mean_square_ = 0.0; }

  struct Flags {
    bool peak = false;        // cut by the peak rating
    bool continuous = false;  // cut by the thermal model
  };
  // Per tick: returns `force` scaled (direction kept) so that |F| <= peak and the thermal model
  // stays within the continuous rating over `dt`. A non-positive or non-finite dt counts as 0.
  Eigen::Vector3d Apply(const Eigen::Vector3d& force, double dt, Flags* flags) noexcept;

  // sqrt of the thermal model's mean square force, N.
  double thermal_rms() const;
  double peak_force() const { return peak_; }
  double continuous_force() const { return continuous_; }

 private:
  double peak_ = 0.0;
  double continuous_ = 0.0;
  double window_ = 1.0;
  double mean_square_ = 0.0;
};

}  // namespace fitfeel
