#pragma once

// The subset of the OpenHaptics HD API (3D Systems, formerly SensAble) this plugin uses, declared
// here so that the project builds without the SDK; the library itself is loaded at run time.
//
// Types, signatures and numeric values are those of the SDK headers HD/hdDefines.h,
// HD/hdDevice.h and HD/hdScheduler.h (OpenHaptics 3.x), as published in public mirrors of the SDK
// headers, e.g. github.com/hhmai/PhantomAPI include/HD/hdDefines.h (version 3.30 of the defines),
// and cross-checked against other projects that redeclare them for dlopen. On Linux HDAPIENTRY and
// HDCALLBACK are empty (C calling convention).

#include <climits>

extern "C" {

typedef unsigned int HDuint;
typedef unsigned char HDboolean;
typedef unsigned long HDulong;
typedef unsigned short HDushort;
typedef int HDint;
typedef double HDdouble;
typedef unsigned int HDerror;
typedef unsigned int HDenum;
typedef const char* HDstring;
typedef unsigned int HHD;

typedef struct {
  HDerror errorCode;      // HD_ error code
  int internalErrorCode;  // the device's own code
  HHD hHD;                // device current when the error occurred
} HDErrorInfo;

// hdScheduler.h
typedef unsigned int HDCallbackCode;
typedef unsigned long HDSchedulerHandle;
typedef HDCallbackCode (*HDSchedulerCallback)(void* pUserData);

}  // extern "C"

// Error codes (hdDefines.h).
#define HD_SUCCESS 0x0000
#define HD_INVALID_ENUM 0x0100
#define HD_INVALID_VALUE 0x0101
#define HD_INVALID_OPERATION 0x0102
#define HD_INVALID_INPUT_TYPE 0x0103
#define HD_BAD_HANDLE 0x0104
#define HD_WARM_MOTORS 0x0200
#define HD_EXCEEDED_MAX_FORCE 0x0201
#define HD_EXCEEDED_MAX_FORCE_IMPULSE 0x0202
#define HD_EXCEEDED_MAX_VELOCITY 0x0203
#define HD_FORCE_ERROR 0x0204
#define HD_DEVICE_FAULT 0x0300
#define HD_DEVICE_ALREADY_INITIATED 0x0301
#define HD_COMM_ERROR 0x0302
#define HD_COMM_CONFIG_ERROR 0x0303
#define HD_TIMER_ERROR 0x0304
#define HD_ILLEGAL_BEGIN 0x0400
#define HD_ILLEGAL_END 0x0401
#define HD_FRAME_ERROR 0x0402
#define HD_INVALID_PRIORITY 0x0500
#define HD_SCHEDULER_FULL 0x0501
#define HD_INVALID_LICENSE 0x0600

// Get parameters.
#define HD_CURRENT_BUTTONS 0x2000
#define HD_CURRENT_POSITION 0x2050          // 3 doubles, mm
#define HD_CURRENT_VELOCITY 0x2051          // 3 doubles, mm/s
#define HD_CURRENT_TRANSFORM 0x2052         // 16 doubles, column-major, translation in mm
#define HD_CURRENT_ANGULAR_VELOCITY 0x2053  // 3 doubles, rad/s
#define HD_DEVICE_MODEL_TYPE 0x2501
#define HD_DEVICE_SERIAL_NUMBER 0x2504
#define HD_INPUT_DOF 0x2553
#define HD_OUTPUT_DOF 0x2554
#define HD_USABLE_WORKSPACE_DIMENSIONS 0x2551  // 6 doubles: min x, y, z, max x, y, z (mm)
#define HD_CALIBRATION_STYLE 0x2555
#define HD_UPDATE_RATE 0x2600  // 1 integer, Hz: the servo loop's rate
#define HD_INSTANTANEOUS_UPDATE_RATE 0x2601
#define HD_NOMINAL_MAX_STIFFNESS 0x2602         // N/mm
#define HD_NOMINAL_MAX_FORCE 0x2603             // N
#define HD_NOMINAL_MAX_CONTINUOUS_FORCE 0x2604  // N
#define HD_NOMINAL_MAX_DAMPING 0x2609           // N*s/mm
#define HD_MOTOR_TEMPERATURE 0x2605  // one double per motor, 0 cold .. 1 the driver's cut-off
// Set parameters.
#define HD_CURRENT_FORCE 0x2700  // 3 doubles, N
// Capabilities.
#define HD_FORCE_OUTPUT 0x4000
#define HD_MAX_FORCE_CLAMPING 0x4001
// Scheduler.
#define HD_CALLBACK_DONE 0
#define HD_CALLBACK_CONTINUE 1
#define HD_MAX_SCHEDULER_PRIORITY USHRT_MAX
#define HD_MIN_SCHEDULER_PRIORITY 0
// Calibration.
#define HD_CALIBRATION_OK 0x5000
#define HD_CALIBRATION_NEEDS_UPDATE 0x5001
#define HD_CALIBRATION_NEEDS_MANUAL_INPUT 0x5002
#define HD_CALIBRATION_ENCODER_RESET (1 << 0)
#define HD_CALIBRATION_AUTO (1 << 1)
#define HD_CALIBRATION_INKWELL (1 << 2)
// Devices.
#define HD_INVALID_HANDLE 0xFFFFFFFF
#define HD_DEFAULT_DEVICE nullptr

namespace fitfeel::phantom::hd {

// Function pointer types of the entry points used (hdDevice.h, hdScheduler.h).
using InitDeviceFn = HHD (*)(HDstring);
using DisableDeviceFn = void (*)(HHD);
using MakeCurrentDeviceFn = void (*)(HHD);
using GetErrorFn = HDErrorInfo (*)();
using GetErrorStringFn = HDstring (*)(HDerror);
using EnableFn = void (*)(HDenum);
using CheckCalibrationFn = HDenum (*)();
using UpdateCalibrationFn = void (*)(HDenum);
using GetDoublevFn = void (*)(HDenum, HDdouble*);
using GetIntegervFn = void (*)(HDenum, HDint*);
using GetStringFn = HDstring (*)(HDenum);
using SetDoublevFn = void (*)(HDenum, const HDdouble*);
using FrameFn = void (*)(HHD);
using ScheduleAsynchronousFn = HDSchedulerHandle (*)(HDSchedulerCallback, void*, HDushort);
using ScheduleSynchronousFn = void (*)(HDSchedulerCallback, void*, HDushort);
using UnscheduleFn = void (*)(HDSchedulerHandle);
using SchedulerFn = void (*)();
// Not OpenHaptics: the optional clock of a simulated device (phantom_hd_library.h).
using DeviceTimeFn = double (*)();

// Motors the HD_MOTOR_TEMPERATURE array can report (6-DOF output devices have six).
constexpr int kMaxMotors = 6;

inline bool IsForceError(HDerror code) { return code >= HD_WARM_MOTORS && code <= HD_FORCE_ERROR; }

}  // namespace fitfeel::phantom::hd
