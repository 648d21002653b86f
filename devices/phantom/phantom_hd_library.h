#pragma once

#include <string>
#include <vector>

#include "devices/phantom/phantom_hd_api.h"

namespace fitfeel::phantom::hd {

// The OpenHaptics HD library, loaded with dlopen. Never unloaded: the vendor's servo thread may
// outlive any object of ours by a tick.
struct Library {
  std::string path;  // what was loaded
  InitDeviceFn hdInitDevice = nullptr;
  DisableDeviceFn hdDisableDevice = nullptr;
  MakeCurrentDeviceFn hdMakeCurrentDevice = nullptr;
  GetErrorFn hdGetError = nullptr;
  GetErrorStringFn hdGetErrorString = nullptr;
  EnableFn hdEnable = nullptr;
  CheckCalibrationFn hdCheckCalibration = nullptr;
  UpdateCalibrationFn hdUpdateCalibration = nullptr;
  GetDoublevFn hdGetDoublev = nullptr;
  GetIntegervFn hdGetIntegerv = nullptr;
  GetStringFn hdGetString = nullptr;
  SetDoublevFn hdSetDoublev = nullptr;
  FrameFn hdBeginFrame = nullptr;
  FrameFn hdEndFrame = nullptr;
  ScheduleAsynchronousFn hdScheduleAsynchronous = nullptr;
  ScheduleSynchronousFn hdScheduleSynchronous = nullptr;
  UnscheduleFn hdUnschedule = nullptr;
  SchedulerFn hdStartScheduler = nullptr;
  SchedulerFn hdStopScheduler = nullptr;
  // Optional, and never in OpenHaptics: a simulated device's own clock, s (`double
  // fitfeel_hd_device_time(void)`). Where the library has it, the plugin takes the servo ticks'
  // times and the calibration wait from it instead of the host's steady clock, so that a
  // simulation whose clock counts servo periods runs the same on a loaded machine as on an idle
  // one. Null for the real library.
  DeviceTimeFn fitfeel_hd_device_time = nullptr;
};

// Where the library is looked for: $FITFEEL_HD_LIBRARY alone when set, else the dynamic loader's
// search for libHD.so and the SDK's usual install folders.
std::vector<std::string> CandidatePaths();

// Loads the library and resolves every entry point; throws UserError naming the library, every
// path tried with the loader's reason, and the environment variable that overrides it.
Library LoadLibrary();

// "HD_COMM_ERROR (0x0302): <library's text>, internal code 5".
std::string DescribeError(const Library& hd, const HDErrorInfo& error);

}  // namespace fitfeel::phantom::hd
