#pragma once

#include <cmath>

#include "framework/device/device.h"

namespace fitfeel {

// What a device state (live or recorded) may hold and still make physical sense. No haptic
// device's workspace reaches beyond a metre, so 10 m is an order of magnitude past any; a hand
// moves at a few m/s and turns at a few rad/s (100 m/s and 1000 rad/s are beyond any device's
// encoders); no part pair presses harder than 10 MN (a 3 m shrink fit); a session is shorter than
// a year. One set of numbers for the recording reader and the scheduler's live check.
inline constexpr double kMaxDeviceTime = 3.2e7;           // s
inline constexpr double kMaxDevicePosition = 10.0;        // m, each coordinate
inline constexpr double kMaxDeviceSpeed = 100.0;          // m/s, each component
inline constexpr double kMaxDeviceAngularSpeed = 1000.0;  // rad/s, each component
inline constexpr double kMaxDeviceForce = 1e7;            // N (torques: N*m), each component
// A quaternion from a rotation is unit to ~1e-16; anything off by more than this is not a pose.
inline constexpr double kMaxQuaternionNormError = 1e-6;

// Whether a live device state is finite and inside the bounds above (positions, speeds, the
// orientation's unit length). Cheap: for the tick.
inline bool DeviceStateInBounds(const DeviceState& s) noexcept {
  auto within = [](const auto& v, double bound) {
    return v.allFinite() && v.cwiseAbs().maxCoeff() <= bound;
  };
  return within(s.position, kMaxDevicePosition) && within(s.velocity, kMaxDeviceSpeed) &&
         within(s.angular_velocity, kMaxDeviceAngularSpeed) &&
         s.orientation.coeffs().allFinite() &&
         std::abs(s.orientation.squaredNorm() - 1.0) <= kMaxQuaternionNormError;
}

}  // namespace fitfeel
