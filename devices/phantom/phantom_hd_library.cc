#include "devices/phantom/phantom_hd_library.h"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

#include "framework/core/error.h"

namespace fitfeel::phantom::hd {
namespace {

constexpr const char* kEnvironment = "FITFEEL_HD_LIBRARY";

const char* ErrorName(HDerror code) {
  switch (code) {
    case HD_SUCCESS:
      return "HD_SUCCESS";
    case HD_INVALID_ENUM:
      return "HD_INVALID_ENUM";
    case HD_INVALID_VALUE:
      return "HD_INVALID_VALUE";
    case HD_INVALID_OPERATION:
      return "HD_INVALID_OPERATION";
    case HD_INVALID_INPUT_TYPE:
      return "HD_INVALID_INPUT_TYPE";
    case HD_BAD_HANDLE:
      return "HD_BAD_HANDLE";
    case HD_WARM_MOTORS:
      return "HD_WARM_MOTORS";
    case HD_EXCEEDED_MAX_FORCE:
      return "HD_EXCEEDED_MAX_FORCE";
    case HD_EXCEEDED_MAX_FORCE_IMPULSE:
      return "HD_EXCEEDED_MAX_FORCE_IMPULSE";
    case HD_EXCEEDED_MAX_VELOCITY:
      return "HD_EXCEEDED_MAX_VELOCITY";
    case HD_FORCE_ERROR:
      return "HD_FORCE_ERROR";
    case HD_DEVICE_FAULT:
      return "HD_DEVICE_FAULT";
    case HD_DEVICE_ALREADY_INITIATED:
      return "HD_DEVICE_ALREADY_INITIATED";
    case HD_COMM_ERROR:
      return "HD_COMM_ERROR";
    case HD_COMM_CONFIG_ERROR:
      return "HD_COMM_CONFIG_ERROR";
    case HD_TIMER_ERROR:
      return "HD_TIMER_ERROR";
    case HD_ILLEGAL_BEGIN:
      return "HD_ILLEGAL_BEGIN";
    case HD_ILLEGAL_END:
      return "HD_ILLEGAL_END";
    case HD_FRAME_ERROR:
      return "HD_FRAME_ERROR";
    case HD_INVALID_PRIORITY:
      return "HD_INVALID_PRIORITY";
    case HD_SCHEDULER_FULL:
      return "HD_SCHEDULER_FULL";
    case HD_INVALID_LICENSE:
      return "HD_INVALID_LICENSE";
  }
  return "unknown HD error";
}

template <typename Fn>
void Resolve(void* handle, const char* name, const std::string& path, Fn* out) {
  dlerror();
  void* symbol = dlsym(handle, name);
  if (symbol == nullptr) {
    throw UserError("OpenHaptics HD library " + path + " lacks " + name +
                    " (not an HD library, or an unsupported version)");
  }
  *out = reinterpret_cast<Fn>(symbol);
}

}  // namespace

std::vector<std::string> CandidatePaths() {
  if (const char* env = std::getenv(kEnvironment); env != nullptr && *env != '\0') {
    return {env};
  }
  // The runtime packages install only the versioned names (libHD.so.3.4.0 and its soname
  // links); the unversioned link comes with the developer files, so both are looked for.
  std::vector<std::string> paths;
  for (const char* dir : {"", "/usr/lib/", "/usr/lib64/", "/usr/local/lib/",
                          "/usr/lib/x86_64-linux-gnu/", "/opt/OpenHaptics/Developer/lib/"}) {
    for (const char* name : {"libHD.so", "libHD.so.3.4", "libHD.so.3.4.0", "libHD.so.3"}) {
      paths.push_back(std::string(dir) + name);
    }
  }
  return paths;
}

Library LoadLibrary() {
  std::string tried;
  void* handle = nullptr;
  Library hd;
  for (const std::string& path : CandidatePaths()) {
    handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle != nullptr) {
      hd.path = path;
      break;
    }
    const char* why = dlerror();
    tried += "\n  " + path + ": " + (why ? why : "not found");
  }
  if (handle == nullptr) {
    throw UserError(
        "the Phantom device needs the OpenHaptics HD library (libHD.so), which was not found; "
        "tried:" +
        tried + "\nInstall the OpenHaptics for Linux runtime or set " + kEnvironment +
        " to the library's path (with its file name, e.g. /opt/OpenHaptics/lib/libHD.so.3.4.0).");
  }
  Resolve(handle, "hdInitDevice", hd.path, &hd.hdInitDevice);
  Resolve(handle, "hdDisableDevice", hd.path, &hd.hdDisableDevice);
  Resolve(handle, "hdMakeCurrentDevice", hd.path, &hd.hdMakeCurrentDevice);
  Resolve(handle, "hdGetError", hd.path, &hd.hdGetError);
  Resolve(handle, "hdGetErrorString", hd.path, &hd.hdGetErrorString);
  Resolve(handle, "hdEnable", hd.path, &hd.hdEnable);
  Resolve(handle, "hdCheckCalibration", hd.path, &hd.hdCheckCalibration);
  Resolve(handle, "hdUpdateCalibration", hd.path, &hd.hdUpdateCalibration);
  Resolve(handle, "hdGetDoublev", hd.path, &hd.hdGetDoublev);
  Resolve(handle, "hdGetIntegerv", hd.path, &hd.hdGetIntegerv);
  Resolve(handle, "hdGetString", hd.path, &hd.hdGetString);
  Resolve(handle, "hdSetDoublev", hd.path, &hd.hdSetDoublev);
  Resolve(handle, "hdBeginFrame", hd.path, &hd.hdBeginFrame);
  Resolve(handle, "hdEndFrame", hd.path, &hd.hdEndFrame);
  Resolve(handle, "hdScheduleAsynchronous", hd.path, &hd.hdScheduleAsynchronous);
  Resolve(handle, "hdScheduleSynchronous", hd.path, &hd.hdScheduleSynchronous);
  Resolve(handle, "hdUnschedule", hd.path, &hd.hdUnschedule);
  Resolve(handle, "hdStartScheduler", hd.path, &hd.hdStartScheduler);
  Resolve(handle, "hdStopScheduler", hd.path, &hd.hdStopScheduler);
  hd.fitfeel_hd_device_time =
      reinterpret_cast<DeviceTimeFn>(dlsym(handle, "fitfeel_hd_device_time"));
  return hd;
}

std::string DescribeError(const Library& hd, const HDErrorInfo& error) {
  char code[16];
  std::snprintf(code, sizeof(code), "0x%04X", error.errorCode);
  std::string out = std::string(ErrorName(error.errorCode)) + " (" + code + ")";
  if (hd.hdGetErrorString != nullptr) {
    if (HDstring text = hd.hdGetErrorString(error.errorCode); text != nullptr && *text != '\0') {
      out += ": ";
      out += text;
    }
  }
  out += ", internal code " + std::to_string(error.internalErrorCode);
  return out;
}

}  // namespace fitfeel::phantom::hd
