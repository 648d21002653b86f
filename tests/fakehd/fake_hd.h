#pragma once

// Introspection of the fake OpenHaptics HD library, for the tests that drive it (look it up with
// dlsym on the same library the plugin loaded).
//
// Scenario, read from the environment at each hdInitDevice:
//   FAKEHD_INIT_FAIL=1            hdInitDevice fails with HD_COMM_ERROR on the error stack
//   FAKEHD_CALIBRATION=ok|update|manual   what hdCheckCalibration reports (update: until
//                                 hdUpdateCalibration with a supported style)
//   FAKEHD_CALIBRATION_STYLES=n   HD_CALIBRATION_STYLE bit mask (default: auto | inkwell)
//   FAKEHD_FORCE_ERROR_FRAME=n    push HD_EXCEEDED_MAX_FORCE at the end of frame n (1-based)
//   FAKEHD_MODEL=name             HD_DEVICE_MODEL_TYPE (default "PHANTOM Desktop")
//   FAKEHD_MAX_FORCE=N            HD_NOMINAL_MAX_FORCE (default 7.9)
//   FAKEHD_MAX_CONTINUOUS_FORCE=N HD_NOMINAL_MAX_CONTINUOUS_FORCE (default 1.75)
// The device moves the stylus along a known path in millimetres (see fake_hd.cc) and the servo
// thread calls the scheduled callbacks every millisecond on absolute deadlines.

#include <cstdint>

extern "C" {

struct FakeHdStats {
  std::uint64_t frames;        // completed hdBeginFrame/hdEndFrame pairs
  std::uint64_t frame_errors;  // begin without end, end without begin, set outside a frame
  std::uint64_t calibration_updates;
  std::uint64_t force_output_enabled;  // 1 when HD_FORCE_OUTPUT is on
  std::uint64_t initialized;           // 1 between hdInitDevice and hdDisableDevice
  std::uint64_t error_frame;           // frame at whose end the force error was pushed (0: none)
  std::uint64_t nonzero_after_error;   // frames with force within 50 frames after that error
  double max_force;                    // largest |force| commanded, N
  double last_force[3];                // force commanded in the last frame, N
  double servo_seconds;                // servo thread run time, s
};

typedef void (*FakeHdStatsFn)(FakeHdStats*);
}
