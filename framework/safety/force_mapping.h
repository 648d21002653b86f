#pragma once

#include "framework/core/export.h"
#include "framework/device/device.h"
#include "framework/safety/safety_settings.h"

namespace fitfeel {

// Human force perception saturates: above about 3-4 N the detail of a rendered force is no longer
// felt better, even on devices that push harder (O'Malley & Goldfarb, IEEE/ASME Transactions on
// Mechatronics 7(3), 2002). The perceptual map spends no device force above this.
inline constexpr double kPerceptionSaturationForce = 3.5;  // N
// Default knee of the perceptual map: below it the scene's force is rendered as is.
inline constexpr double kDefaultMappingKnee = 0.1;  // N
// Default scene top: the scene force the perceptual map renders at the device top. The largest
// press-in force of an ISO 286 H7/s6 fit at 20 mm, as the shipped fits scenes render it, is
// 18.2 kN; 20 kN rounds it up.
inline constexpr double kDefaultMappingTop = 20e3;  // N

// How the safety chain turns the magnitude of the scene's force (physical N) into the device's
// (device N). The direction of the force is kept; torques are scaled by the same ratio f / F.
//
// kLinear: f = force_scale F, one factor for every force. A Touch (3.3 N peak, 0.88 N
// continuous) rendering scenes from 0.3 N (a clearance fit's friction) to 18 kN (a press fit) with
// one factor either loses the small forces or renders every press fit alike.
//
// kPerceptual: f = F up to the knee f_k; above it the power law f = f_k (F / f_k)^gamma with
// gamma = ln(f_top / f_k) / ln(F_top / f_k), so that the scene top F_top lands on the device top
// f_top. Above F_top the same law goes on (the force limiter cuts what the device cannot give).
// The law maps equal ratios of scene force to equal ratios of device force, which is how force
// differences are perceived: the just-noticeable difference is a fixed fraction of the force
// (Weber fraction about 7 % for 2.5-10 N, Pang, Tan & Durlach, Perception & Psychophysics 50(6),
// 1991), so a ratio of scene forces stays a ratio the hand can tell apart as long as gamma keeps
// it above that fraction.
//
// The map is continuous and monotone; its slope is 1 up to the knee and gamma < 1 times the ratio
// f / F (itself <= 1) above it, so it is concave and its slope never exceeds 1. Neither the slope
// nor the ratio f / F (what a force perpendicular to the current one meets) exceeds 1: the device
// never renders a stiffness above the one the scene (or the coupling) gives it, so the map adds no
// energy to a passive rendering.
//
// Configured at prepare time; Map, Slope and Ratio are noexcept and allocate nothing.
class FITFEEL_API ForceMapping {
 public:
  // f = scale F. Throws UserError unless scale is positive and finite.
  static ForceMapping Linear(double scale);
  // The perceptual map. Throws UserError unless 0 < knee < device_top < scene_top, all finite
  // (device_top >= scene_top would give a slope above 1).
  static ForceMapping Perceptual(double knee, double scene_top, double device_top);

  // The device force for a scene force magnitude, N (0 for a non-positive or non-finite one).
  double Map(double scene_newtons) const noexcept;
  // d Map / dF at this scene force, device N per scene N (1 at and below the knee).
  double Slope(double scene_newtons) const noexcept;
  // Map(F) / F, the factor applied to the force vector and the torque; Slope(0) for F = 0.
  double Ratio(double scene_newtons) const noexcept;

  ForceMappingKind kind() const { return kind_; }
  double scale() const { return scale_; }  // kLinear only; 1 for kPerceptual
  double knee() const { return knee_; }
  double exponent() const { return exponent_; }
  double scene_top() const { return scene_top_; }
  double device_top() const { return device_top_; }

 private:
  ForceMappingKind kind_ = ForceMappingKind::kLinear;
  double scale_ = 1.0;
  double knee_ = 0.0;
  double exponent_ = 1.0;
  double scene_top_ = 0.0;
  double device_top_ = 0.0;
};

// The device top f_top of the perceptual map: the smallest of
//   - the spec's peak force (what the motors give at all),
//   - kPerceptionSaturationForce (what the hand resolves),
//   - the force the device holds for one thermal window: the chain's thermal model (ForceLimiter)
//     reaches the continuous rating after a constant force F held for one time constant when
//     F^2 (1 - 1/e) = max_continuous_force^2, i.e. F = max_continuous_force / sqrt(1 - 1/e).
// A device without a motor (infinite limits) gets kPerceptionSaturationForce. For a Touch:
// 0.88 N / 0.795 = 1.107 N.
FITFEEL_API double PerceptualDeviceTop(const DeviceSpec& spec);

// The mapping the chain renders with: settings.force_mapping if given, else the spec's. Linear
// takes `force_scale` (the chain's, after physical_full_scale); perceptual the settings' knee and
// top and PerceptualDeviceTop(spec). Throws UserError naming the device.
FITFEEL_API ForceMapping MakeForceMapping(const SafetySettings& settings, const DeviceSpec& spec,
                                          double force_scale);

}  // namespace fitfeel
