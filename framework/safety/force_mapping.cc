#include "framework/safety/force_mapping.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

bool PositiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

ForceMapping ForceMapping::Linear(double scale) {
  if (!PositiveFinite(scale)) throw UserError("force mapping: the scale must be positive");
  ForceMapping m;
  m.kind_ = ForceMappingKind::kLinear;
  m.scale_ = scale;
  return m;
}

ForceMapping ForceMapping::Perceptual(double knee, double scene_top, double device_top) {
  if (!PositiveFinite(knee) || !PositiveFinite(scene_top) || !PositiveFinite(device_top) ||
      !(knee < device_top) || !(device_top < scene_top)) {
    std::ostringstream msg;
    msg << "perceptual force mapping needs 0 < knee < device top < scene top; got knee " << knee
        << " N, device top " << device_top << " N, scene top " << scene_top << " N";
    throw UserError(msg.str());
  }
  ForceMapping m;
  m.kind_ = ForceMappingKind::kPerceptual;
  m.knee_ = knee;
  m.scene_top_ = scene_top;
  m.device_top_ = device_top;
  m.exponent_ = std::log(device_top / knee) / std::log(scene_top / knee);
  return m;
}

double ForceMapping::Map(double f) const noexcept {
  if (!(f > 0.0) || !std::isfinite(f)) return 0.0;
  if (kind_ == ForceMappingKind::kLinear) return scale_ * f;
  if (f <= knee_) return f;
  return knee_ * std::pow(f / knee_, exponent_);
}

double ForceMapping::Slope(double f) const noexcept {
  if (kind_ == ForceMappingKind::kLinear) return scale_;
  if (!(f > knee_)) return 1.0;
  if (!std::isfinite(f)) return 0.0;
  return exponent_ * Map(f) / f;
}

double ForceMapping::Ratio(double f) const noexcept {
  if (kind_ == ForceMappingKind::kLinear) return scale_;
  if (!(f > knee_)) return 1.0;
  if (!std::isfinite(f)) return 0.0;
  return Map(f) / f;
}

double PerceptualDeviceTop(const DeviceSpec& spec) {
  // The thermal model's mean square after a constant force held for one time constant.
  const double one_window = std::sqrt(1.0 - std::exp(-1.0));
  double top = kPerceptionSaturationForce;
  if (spec.max_force > 0.0) top = std::min(top, spec.max_force);
  if (spec.max_continuous_force > 0.0) top = std::min(top, spec.max_continuous_force / one_window);
  return top;
}

ForceMapping MakeForceMapping(const SafetySettings& settings, const DeviceSpec& spec,
                              double force_scale) {
  const ForceMappingKind kind = settings.force_mapping.value_or(spec.force_mapping);
  if (kind == ForceMappingKind::kLinear) return ForceMapping::Linear(force_scale);
  try {
    return ForceMapping::Perceptual(settings.mapping_knee, settings.mapping_top,
                                    PerceptualDeviceTop(spec));
  } catch (const UserError& e) {
    throw UserError("safety (device '" + spec.model + "'): " + e.what());
  }
}

}  // namespace fitfeel
