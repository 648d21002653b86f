#pragma once

// Introspection of the fake OpenHaptics HD library, for the tests that drive it (look it up with
// dlsym on the same library the plugin loaded).
//
// It behaves as the real driver does where a plugin can get it wrong:
//  - the motors keep the last force set until another is set (not zero each frame);
//  - a watchdog: a frame that begins more than FAKEHD_WATCHDOG_MS after the previous one ended,
//    while a force is held, cuts the force and raises HD_FORCE_ERROR;
//  - its clock counts servo periods, not wall time, and the plugin reads it through the optional
//    entry point fitfeel_hd_device_time: a machine that stalls the test's threads changes nothing
//    it measures (the watchdog, the fault window, the ramps, the manual calibration's wait);
//  - calibration (hdCheckCalibration, hdUpdateCalibration) answers only inside the running
//    scheduler's callbacks; elsewhere it raises HD_INVALID_OPERATION and reports "needs update";
//  - warm motors persist: once hot, every frame that commands force raises HD_WARM_MOTORS until
//    the motors have cooled (HD_MOTOR_TEMPERATURE falls while no force is commanded);
//  - the stylus rotates about every axis and its velocity is noisy.
//
// Scenario, read from the environment at each hdInitDevice:
//   FAKEHD_INIT_FAIL=1            hdInitDevice fails with HD_COMM_ERROR on the error stack
//   FAKEHD_CALIBRATION=ok|update|manual   what hdCheckCalibration reports (update: until
//                                 hdUpdateCalibration with a supported style; manual: until
//                                 FAKEHD_MANUAL_SECONDS of servo time after init, when the "user"
//                                 inkwells it)
//   FAKEHD_CALIBRATION_STYLES=n   HD_CALIBRATION_STYLE bit mask (default: auto | inkwell)
//   FAKEHD_FORCE_ERROR_FRAME=n    push HD_EXCEEDED_MAX_FORCE at the end of frame n (1-based)
//   FAKEHD_VELOCITY_ERROR_FRAME=n push HD_EXCEEDED_MAX_VELOCITY at the end of frame n
//   FAKEHD_WARM_FRAME=n           the motors are hot (temperature 1) from frame n
//   FAKEHD_TEMPERATURE=t          the motors' temperature at rest, normalized (0.2)
//   FAKEHD_COOL_SECONDS=s         cooling time constant while no force is commanded (0.2)
//   FAKEHD_WATCHDOG_MS=ms         watchdog limit between frames (50)
//   FAKEHD_RATE=Hz                HD_UPDATE_RATE and the servo thread's rate (1000)
//   FAKEHD_PATH=circle|insert     the stylus path (circle; see fake_hd.cc)
//   FAKEHD_INSERT_SPEED=mm/s      insert path: speed into the screen (20)
//   FAKEHD_INSERT_OFFSET=mm       insert path: offset along device x (0.1)
//   FAKEHD_INSERT_DEPTH=mm        insert path: where it stops, beyond its start (30)
//   FAKEHD_VELOCITY_NOISE=mm/s    standard deviation of the velocity's noise (2)
//   FAKEHD_MODEL=name             HD_DEVICE_MODEL_TYPE (default "PHANTOM Desktop")
//   FAKEHD_MAX_FORCE=N            HD_NOMINAL_MAX_FORCE (default 7.9)
//   FAKEHD_MAX_CONTINUOUS_FORCE=N HD_NOMINAL_MAX_CONTINUOUS_FORCE (default 1.75)
//   FAKEHD_MAX_STIFFNESS=N/mm     HD_NOMINAL_MAX_STIFFNESS (default 1.0)
// The servo thread calls the scheduled callbacks at FAKEHD_RATE on absolute deadlines; the path
// advances with the frame count, so it is the same however late the thread runs.

#include <cstdint>

extern "C" {

struct FakeHdStats {
  std::uint64_t frames;        // completed hdBeginFrame/hdEndFrame pairs
  std::uint64_t frame_errors;  // begin without end, end without begin, set outside a frame
  std::uint64_t calibration_updates;
  std::uint64_t calibration_outside_scheduler;  // calibration calls refused off the servo thread
  std::uint64_t force_output_enabled;           // 1 when HD_FORCE_OUTPUT is on
  std::uint64_t initialized;                    // 1 between hdInitDevice and hdDisableDevice
  std::uint64_t error_frame;          // frame at whose end the force error was pushed (0: none)
  std::uint64_t nonzero_after_error;  // frames with force within 50 frames after that error
  std::uint64_t velocity_error_frame;
  std::uint64_t warm_errors;      // HD_WARM_MOTORS raised
  std::uint64_t watchdog_faults;  // frames the watchdog faulted
  std::uint64_t late_frames;      // servo wake-ups more than a period late
  std::uint64_t hot_forced_frames;  // frames that held force while the motors were hot
  double max_force;                 // largest |force| held, N
  double last_force[3];             // force held after the last frame, N
  double servo_seconds;             // servo thread run time, s
};

typedef void (*FakeHdStatsFn)(FakeHdStats*);
}
