// A fake OpenHaptics HD library (libHD.so) for the tests: same entry points and constants as the
// real one (devices/phantom/phantom_hd_api.h), a scripted device, a servo thread at 1 kHz.

#include "tests/fakehd/fake_hd.h"

#include <time.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "devices/phantom/phantom_hd_api.h"

#define FAKEHD_EXPORT extern "C" __attribute__((visibility("default")))

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Scheduled {
  HDSchedulerHandle handle;
  HDSchedulerCallback callback;
  void* data;
};

struct State {
  std::mutex mutex;  // guards errors and scheduled (touched from both threads)
  std::vector<HDErrorInfo> errors;
  std::vector<Scheduled> scheduled;
  HDSchedulerHandle next_handle = 1;
  std::thread servo;
  std::atomic<bool> stop{false};
  bool running = false;

  bool initialized = false;
  bool force_output = false;
  bool in_frame = false;
  HDenum calibration = HD_CALIBRATION_OK;
  HDint calibration_styles = HD_CALIBRATION_AUTO | HD_CALIBRATION_INKWELL;
  std::uint64_t force_error_frame = 0;
  std::string model = "PHANTOM Desktop";
  double max_force = 7.9;
  double max_continuous = 1.75;

  FakeHdStats stats{};
  double force[3] = {0, 0, 0};
};

State& S() {
  static State state;
  return state;
}

void Push(HDerror code, int internal = 0) {
  std::lock_guard<std::mutex> lock(S().mutex);
  S().errors.push_back(HDErrorInfo{code, internal, 0});
}

double EnvDouble(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v ? std::strtod(v, nullptr) : fallback;
}

// Device time: frames at the nominal 1 kHz, so the path is the same however late the thread runs.
double DeviceTime() { return static_cast<double>(S().stats.frames) * 1e-3; }

// The stylus path, in millimetres: a 0.5 Hz circle in x-y of radius 20 mm, z fixed at 15 mm,
// rotating about y by 0.2 sin(t) rad; button 1 pressed during odd seconds.
void Path(double t, double* position, double* velocity, double* transform, double* angular,
          HDint* buttons) {
  const double w = 2.0 * kPi * 0.5;
  position[0] = 20.0 * std::sin(w * t);
  position[1] = 20.0 * std::cos(w * t);
  position[2] = 15.0;
  velocity[0] = 20.0 * w * std::cos(w * t);
  velocity[1] = -20.0 * w * std::sin(w * t);
  velocity[2] = 0.0;
  const double a = 0.2 * std::sin(t);
  const double c = std::cos(a), s = std::sin(a);
  // Column-major rotation about y, then the translation.
  const double m[16] = {c, 0, -s, 0, 0,           1,           0,           0,
                        s, 0, c,  0, position[0], position[1], position[2], 1};
  std::memcpy(transform, m, sizeof(m));
  angular[0] = 0.0;
  angular[1] = 0.2 * std::cos(t);
  angular[2] = 0.0;
  *buttons = (static_cast<long>(t) % 2 == 1) ? 1 : 0;
}

}  // namespace

FAKEHD_EXPORT HHD hdInitDevice(HDstring) {
  State& st = S();
  {
    std::lock_guard<std::mutex> lock(st.mutex);
    st.errors.clear();
  }
  st.stats = FakeHdStats{};
  st.force[0] = st.force[1] = st.force[2] = 0.0;
  const char* fail = std::getenv("FAKEHD_INIT_FAIL");
  if (fail && std::strcmp(fail, "1") == 0) {
    Push(HD_COMM_ERROR, 5);
    return HD_INVALID_HANDLE;
  }
  const char* cal = std::getenv("FAKEHD_CALIBRATION");
  st.calibration = HD_CALIBRATION_OK;
  if (cal && std::strcmp(cal, "update") == 0) st.calibration = HD_CALIBRATION_NEEDS_UPDATE;
  if (cal && std::strcmp(cal, "manual") == 0) st.calibration = HD_CALIBRATION_NEEDS_MANUAL_INPUT;
  st.calibration_styles = static_cast<HDint>(
      EnvDouble("FAKEHD_CALIBRATION_STYLES", HD_CALIBRATION_AUTO | HD_CALIBRATION_INKWELL));
  st.force_error_frame = static_cast<std::uint64_t>(EnvDouble("FAKEHD_FORCE_ERROR_FRAME", 0));
  const char* model = std::getenv("FAKEHD_MODEL");
  st.model = model ? model : "PHANTOM Desktop";
  st.max_force = EnvDouble("FAKEHD_MAX_FORCE", 7.9);
  st.max_continuous = EnvDouble("FAKEHD_MAX_CONTINUOUS_FORCE", 1.75);
  st.initialized = true;
  st.stats.initialized = 1;
  return 1;
}

FAKEHD_EXPORT void hdDisableDevice(HHD) {
  S().initialized = false;
  S().force_output = false;
  S().stats.initialized = 0;
  S().stats.force_output_enabled = 0;
}

FAKEHD_EXPORT void hdMakeCurrentDevice(HHD handle) {
  if (handle != 1) Push(HD_BAD_HANDLE);
}

FAKEHD_EXPORT HDErrorInfo hdGetError() {
  std::lock_guard<std::mutex> lock(S().mutex);
  if (S().errors.empty()) return HDErrorInfo{HD_SUCCESS, 0, 0};
  const HDErrorInfo top = S().errors.back();
  S().errors.pop_back();
  return top;
}

FAKEHD_EXPORT HDstring hdGetErrorString(HDerror code) {
  switch (code) {
    case HD_COMM_ERROR:
      return "Communication error (fake)";
    case HD_EXCEEDED_MAX_FORCE:
      return "Exceeded max force (fake)";
    default:
      return "fake HD error";
  }
}

FAKEHD_EXPORT void hdEnable(HDenum capability) {
  if (!S().initialized) {
    Push(HD_INVALID_OPERATION);
    return;
  }
  if (capability == HD_FORCE_OUTPUT) {
    S().force_output = true;
    S().stats.force_output_enabled = 1;
  } else if (capability != HD_MAX_FORCE_CLAMPING) {
    Push(HD_INVALID_ENUM);
  }
}

FAKEHD_EXPORT HDenum hdCheckCalibration() { return S().calibration; }

FAKEHD_EXPORT void hdUpdateCalibration(HDenum style) {
  if (!(style & static_cast<HDenum>(S().calibration_styles))) {
    Push(HD_INVALID_VALUE);
    return;
  }
  ++S().stats.calibration_updates;
  if (S().calibration == HD_CALIBRATION_NEEDS_UPDATE) S().calibration = HD_CALIBRATION_OK;
}

FAKEHD_EXPORT void hdGetDoublev(HDenum what, HDdouble* out) {
  State& st = S();
  double position[3], velocity[3], transform[16], angular[3];
  HDint buttons = 0;
  switch (what) {
    case HD_NOMINAL_MAX_FORCE:
      out[0] = st.max_force;
      return;
    case HD_NOMINAL_MAX_CONTINUOUS_FORCE:
      out[0] = st.max_continuous;
      return;
    case HD_NOMINAL_MAX_STIFFNESS:
      out[0] = 1.0;
      return;  // N/mm
    case HD_NOMINAL_MAX_DAMPING:
      out[0] = 0.005;
      return;  // N*s/mm
    case HD_USABLE_WORKSPACE_DIMENSIONS: {
      const double box[6] = {-80, -60, -60, 80, 60, 60};
      std::memcpy(out, box, sizeof(box));
      return;
    }
    default:
      break;
  }
  if (!st.in_frame) {
    Push(HD_FRAME_ERROR);
    return;
  }
  Path(DeviceTime(), position, velocity, transform, angular, &buttons);
  switch (what) {
    case HD_CURRENT_POSITION:
      std::memcpy(out, position, sizeof(position));
      return;
    case HD_CURRENT_VELOCITY:
      std::memcpy(out, velocity, sizeof(velocity));
      return;
    case HD_CURRENT_TRANSFORM:
      std::memcpy(out, transform, sizeof(transform));
      return;
    case HD_CURRENT_ANGULAR_VELOCITY:
      std::memcpy(out, angular, sizeof(angular));
      return;
    default:
      Push(HD_INVALID_ENUM);
  }
}

FAKEHD_EXPORT void hdGetIntegerv(HDenum what, HDint* out) {
  State& st = S();
  if (what == HD_CALIBRATION_STYLE) {
    *out = st.calibration_styles;
    return;
  }
  if (what == HD_CURRENT_BUTTONS) {
    if (!st.in_frame) {
      Push(HD_FRAME_ERROR);
      return;
    }
    double p[3], v[3], m[16], a[3];
    Path(DeviceTime(), p, v, m, a, out);
    return;
  }
  Push(HD_INVALID_ENUM);
}

FAKEHD_EXPORT HDstring hdGetString(HDenum what) {
  if (what == HD_DEVICE_MODEL_TYPE) return S().model.c_str();
  Push(HD_INVALID_ENUM);
  return "";
}

FAKEHD_EXPORT void hdSetDoublev(HDenum what, const HDdouble* value) {
  State& st = S();
  if (what != HD_CURRENT_FORCE) {
    Push(HD_INVALID_ENUM);
    return;
  }
  if (!st.in_frame) {
    ++st.stats.frame_errors;
    Push(HD_FRAME_ERROR);
    return;
  }
  std::memcpy(st.force, value, sizeof(st.force));
}

FAKEHD_EXPORT void hdBeginFrame(HHD) {
  State& st = S();
  if (st.in_frame) {
    ++st.stats.frame_errors;
    Push(HD_ILLEGAL_BEGIN);
  }
  st.in_frame = true;
}

FAKEHD_EXPORT void hdEndFrame(HHD) {
  State& st = S();
  if (!st.in_frame) {
    ++st.stats.frame_errors;
    Push(HD_ILLEGAL_END);
    return;
  }
  st.in_frame = false;
  ++st.stats.frames;
  const double norm =
      std::sqrt(st.force[0] * st.force[0] + st.force[1] * st.force[1] + st.force[2] * st.force[2]);
  st.stats.max_force = std::max(st.stats.max_force, norm);
  std::memcpy(st.stats.last_force, st.force, sizeof(st.force));
  if (st.stats.error_frame > 0 && st.stats.frames > st.stats.error_frame &&
      st.stats.frames <= st.stats.error_frame + 50 && norm > 0.0) {
    ++st.stats.nonzero_after_error;
  }
  // The real driver raises this when a force above its limit was commanded with clamping off;
  // here the scenario raises it on a chosen frame, and always for a force above the nominal peak.
  if (st.stats.frames == st.force_error_frame || norm > st.max_force) {
    if (st.stats.error_frame == 0) st.stats.error_frame = st.stats.frames;
    Push(HD_EXCEEDED_MAX_FORCE, 1);
  }
  st.force[0] = st.force[1] = st.force[2] = 0.0;  // a frame that sets no force renders none
}

FAKEHD_EXPORT HDSchedulerHandle hdScheduleAsynchronous(HDSchedulerCallback callback, void* data,
                                                       HDushort) {
  std::lock_guard<std::mutex> lock(S().mutex);
  const HDSchedulerHandle handle = S().next_handle++;
  S().scheduled.push_back(Scheduled{handle, callback, data});
  return handle;
}

FAKEHD_EXPORT void hdUnschedule(HDSchedulerHandle handle) {
  std::lock_guard<std::mutex> lock(S().mutex);
  auto& list = S().scheduled;
  for (auto it = list.begin(); it != list.end(); ++it) {
    if (it->handle == handle) {
      list.erase(it);
      return;
    }
  }
}

FAKEHD_EXPORT void hdStartScheduler() {
  State& st = S();
  if (st.running) {
    Push(HD_INVALID_OPERATION);
    return;
  }
  st.stop.store(false);
  st.running = true;
  st.servo = std::thread([&st] {
    timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    timespec next = start;
    std::vector<Scheduled> batch;
    while (!st.stop.load()) {
      {
        std::lock_guard<std::mutex> lock(st.mutex);
        batch = st.scheduled;
      }
      for (const Scheduled& s : batch) {
        if (s.callback(s.data) == HD_CALLBACK_DONE) hdUnschedule(s.handle);
      }
      next.tv_nsec += 1000000;
      if (next.tv_nsec >= 1000000000) {
        next.tv_nsec -= 1000000000;
        ++next.tv_sec;
      }
      timespec now;
      clock_gettime(CLOCK_MONOTONIC, &now);
      const double late = (now.tv_sec - next.tv_sec) + (now.tv_nsec - next.tv_nsec) * 1e-9;
      if (late > 1e-3) {
        next = now;  // a servo loop that fell behind skips ticks rather than bursting
      } else {
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr);
      }
    }
    timespec end;
    clock_gettime(CLOCK_MONOTONIC, &end);
    st.stats.servo_seconds = (end.tv_sec - start.tv_sec) + (end.tv_nsec - start.tv_nsec) * 1e-9;
  });
}

FAKEHD_EXPORT void hdStopScheduler() {
  State& st = S();
  if (!st.running) return;
  st.stop.store(true);
  st.servo.join();
  st.running = false;
}

FAKEHD_EXPORT void fakehd_stats(FakeHdStats* out) { *out = S().stats; }
