// A fake OpenHaptics HD library (libHD.so) for the tests: same entry points and constants as the
// real one (devices/phantom/phantom_hd_api.h), a scripted device, a servo thread at HD_UPDATE_RATE.
// What it imitates of the real driver is listed in fake_hd.h.

#include "tests/fakehd/fake_hd.h"

#include <time.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Geometry>

#include "devices/phantom/phantom_hd_api.h"

#define FAKEHD_EXPORT extern "C" __attribute__((visibility("default")))

namespace {

constexpr double kPi = 3.14159265358979323846;
// Motor temperature, normalized as HD_MOTOR_TEMPERATURE: above it the motors count as hot
// (HD_WARM_MOTORS on any force).
constexpr double kHotTemperature = 0.9;

struct Scheduled {
  HDSchedulerHandle handle;
  HDSchedulerCallback callback;
  void* data;
  bool synchronous;
  bool* finished;  // synchronous: set under the mutex when the callback returned DONE
};

struct State {
  std::mutex mutex;  // guards errors and scheduled (touched from both threads)
  std::condition_variable finished;
  std::vector<HDErrorInfo> errors;
  std::vector<Scheduled> scheduled;
  HDSchedulerHandle next_handle = 1;
  std::thread servo;
  std::thread::id servo_id;
  std::atomic<bool> stop{false};
  bool running = false;

  bool initialized = false;
  bool force_output = false;
  bool in_frame = false;
  HDenum calibration = HD_CALIBRATION_OK;
  double manual_seconds = -1.0;  // < 0: the user never calibrates by hand
  double init_time = 0.0;  // device time (ServoTime) at hdInitDevice
  HDint calibration_styles = HD_CALIBRATION_AUTO | HD_CALIBRATION_INKWELL;
  std::uint64_t force_error_frame = 0;
  std::uint64_t velocity_error_frame = 0;
  std::uint64_t warm_frame = 0;
  double cool_seconds = 0.2;
  double watchdog = 0.05;  // s
  int rate = 1000;
  bool insert_path = false;
  double insert_speed = 20.0, insert_offset = 0.1, insert_depth = 30.0;  // mm/s, mm, mm
  double velocity_noise = 2.0;                                           // mm/s
  std::mt19937_64 noise{12345};
  std::string model = "PHANTOM Desktop";
  double max_force = 7.9;
  double max_continuous = 1.75;
  double max_stiffness = 1.0;  // N/mm

  double ambient = 0.2;  // the motors' temperature at rest
  double temperature = 0.2;
  bool frame_forced = false;  // a force was set in the current frame
  double last_end = 0.0;  // device time of the last hdEndFrame
  bool has_last_end = false;
  FakeHdStats stats{};
  // Servo periods begun since the library loaded: the device's clock. The servo thread counts one
  // per period, so a process that the machine stalls sees no time pass, as if the stall had not
  // happened: whatever the fake measures in time (the watchdog, the "user" calibrating by hand,
  // the clock it gives the plugin) is the same on a busy machine as on an idle one.
  std::atomic<std::uint64_t> servo_periods{0};
  double force[3] = {0, 0, 0};  // what the motors hold
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

double Seconds(const timespec& a, const timespec& b) {
  return static_cast<double>(b.tv_sec - a.tv_sec) + static_cast<double>(b.tv_nsec - a.tv_nsec) * 1e-9;
}

// The device's clock, s: servo periods at the nominal rate.
double ServoTime() {
  return static_cast<double>(S().servo_periods.load(std::memory_order_acquire)) / S().rate;
}

timespec Monotonic() {
  timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return now;
}

bool OnServoThread() { return S().running && std::this_thread::get_id() == S().servo_id; }

// Device time: frames at the nominal rate, so the path is the same however late the thread runs.
double DeviceTime() { return static_cast<double>(S().stats.frames) / S().rate; }

// The stylus's rotation: small turns about x, y and z at incommensurate frequencies.
Eigen::Matrix3d StylusRotation(double t, double amplitude) {
  return (Eigen::AngleAxisd(amplitude * std::sin(1.3 * t), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(amplitude * std::sin(0.7 * t + 0.5), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(amplitude * std::sin(t), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// The stylus, in millimetres.
//  circle: a 0.5 Hz circle in x-y of radius 20 mm, z fixed at 15 mm, turning up to 0.2 rad about
//          every axis; button 1 pressed during odd seconds.
//  insert: from the workspace's centre straight into the screen (-z) at insert_speed, offset
//          insert_offset along x, stopping insert_depth further; the stylus points into the
//          screen, turning up to 2 mrad about every axis; no button.
void Path(double t, double* position, double* velocity, double* transform, double* angular,
          HDint* buttons) {
  const State& st = S();
  double amplitude = 0.2;
  if (st.insert_path) {
    amplitude = 0.002;
    const double travel = std::min(st.insert_speed * t, st.insert_depth);
    position[0] = st.insert_offset;
    position[1] = 0.0;
    position[2] = -travel;
    velocity[0] = velocity[1] = 0.0;
    velocity[2] = st.insert_speed * t < st.insert_depth ? -st.insert_speed : 0.0;
    *buttons = 0;
  } else {
    const double w = 2.0 * kPi * 0.5;
    position[0] = 20.0 * std::sin(w * t);
    position[1] = 20.0 * std::cos(w * t);
    position[2] = 15.0;
    velocity[0] = 20.0 * w * std::cos(w * t);
    velocity[1] = -20.0 * w * std::sin(w * t);
    velocity[2] = 0.0;
    *buttons = (static_cast<long>(t) % 2 == 1) ? 1 : 0;
  }
  const Eigen::Matrix3d r = StylusRotation(t, amplitude);
  // Angular velocity from the rotation's central difference: skew(w) = dR/dt R^T.
  const double h = 1e-5;
  const Eigen::Matrix3d w =
      (StylusRotation(t + h, amplitude) - StylusRotation(t - h, amplitude)) / (2.0 * h) *
      r.transpose();
  angular[0] = 0.5 * (w(2, 1) - w(1, 2));
  angular[1] = 0.5 * (w(0, 2) - w(2, 0));
  angular[2] = 0.5 * (w(1, 0) - w(0, 1));
  for (int c = 0; c < 3; ++c) {
    for (int row = 0; row < 3; ++row) transform[4 * c + row] = r(row, c);  // column-major
    transform[4 * c + 3] = 0.0;
  }
  transform[12] = position[0];
  transform[13] = position[1];
  transform[14] = position[2];
  transform[15] = 1.0;
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
  st.ambient = EnvDouble("FAKEHD_TEMPERATURE", 0.2);
  st.temperature = st.ambient;
  st.has_last_end = false;
  st.noise.seed(12345);
  const char* fail = std::getenv("FAKEHD_INIT_FAIL");
  if (fail && std::strcmp(fail, "1") == 0) {
    Push(HD_COMM_ERROR, 5);
    return HD_INVALID_HANDLE;
  }
  const char* cal = std::getenv("FAKEHD_CALIBRATION");
  st.calibration = HD_CALIBRATION_OK;
  if (cal && std::strcmp(cal, "update") == 0) st.calibration = HD_CALIBRATION_NEEDS_UPDATE;
  if (cal && std::strcmp(cal, "manual") == 0) st.calibration = HD_CALIBRATION_NEEDS_MANUAL_INPUT;
  st.manual_seconds = EnvDouble("FAKEHD_MANUAL_SECONDS", -1.0);
  st.init_time = ServoTime();
  st.calibration_styles = static_cast<HDint>(
      EnvDouble("FAKEHD_CALIBRATION_STYLES", HD_CALIBRATION_AUTO | HD_CALIBRATION_INKWELL));
  st.force_error_frame = static_cast<std::uint64_t>(EnvDouble("FAKEHD_FORCE_ERROR_FRAME", 0));
  st.velocity_error_frame =
      static_cast<std::uint64_t>(EnvDouble("FAKEHD_VELOCITY_ERROR_FRAME", 0));
  st.warm_frame = static_cast<std::uint64_t>(EnvDouble("FAKEHD_WARM_FRAME", 0));
  st.cool_seconds = EnvDouble("FAKEHD_COOL_SECONDS", 0.2);
  st.watchdog = EnvDouble("FAKEHD_WATCHDOG_MS", 50.0) * 1e-3;
  st.rate = static_cast<int>(EnvDouble("FAKEHD_RATE", 1000.0));
  const char* path = std::getenv("FAKEHD_PATH");
  st.insert_path = path != nullptr && std::strcmp(path, "insert") == 0;
  st.insert_speed = EnvDouble("FAKEHD_INSERT_SPEED", 20.0);
  st.insert_offset = EnvDouble("FAKEHD_INSERT_OFFSET", 0.1);
  st.insert_depth = EnvDouble("FAKEHD_INSERT_DEPTH", 30.0);
  st.velocity_noise = EnvDouble("FAKEHD_VELOCITY_NOISE", 2.0);
  const char* model = std::getenv("FAKEHD_MODEL");
  st.model = model ? model : "PHANTOM Desktop";
  st.max_force = EnvDouble("FAKEHD_MAX_FORCE", 7.9);
  st.max_continuous = EnvDouble("FAKEHD_MAX_CONTINUOUS_FORCE", 1.75);
  st.max_stiffness = EnvDouble("FAKEHD_MAX_STIFFNESS", 1.0);
  st.initialized = true;
  st.stats.initialized = 1;
  return 1;
}

FAKEHD_EXPORT void hdDisableDevice(HHD) {
  if (S().running) Push(HD_INVALID_OPERATION);  // the SDK wants the scheduler stopped first
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
    case HD_WARM_MOTORS:
      return "Motors are warm (fake)";
    case HD_EXCEEDED_MAX_VELOCITY:
      return "Exceeded max velocity (fake)";
    case HD_FORCE_ERROR:
      return "Force error: servo watchdog (fake)";
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

FAKEHD_EXPORT HDenum hdCheckCalibration() {
  State& st = S();
  if (!OnServoThread()) {
    ++st.stats.calibration_outside_scheduler;
    Push(HD_INVALID_OPERATION);
    return HD_CALIBRATION_NEEDS_UPDATE;
  }
  if (st.calibration == HD_CALIBRATION_NEEDS_MANUAL_INPUT && st.manual_seconds >= 0.0 &&
      ServoTime() - st.init_time >= st.manual_seconds) {
    st.calibration = HD_CALIBRATION_OK;
  }
  return st.calibration;
}

FAKEHD_EXPORT void hdUpdateCalibration(HDenum style) {
  State& st = S();
  if (!OnServoThread()) {
    ++st.stats.calibration_outside_scheduler;
    Push(HD_INVALID_OPERATION);
    return;
  }
  if (!(style & static_cast<HDenum>(st.calibration_styles))) {
    Push(HD_INVALID_VALUE);
    return;
  }
  ++st.stats.calibration_updates;
  if (st.calibration == HD_CALIBRATION_NEEDS_UPDATE) st.calibration = HD_CALIBRATION_OK;
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
      out[0] = st.max_stiffness;
      return;
    case HD_NOMINAL_MAX_DAMPING:
      out[0] = 0.005;
      return;  // N*s/mm
    case HD_USABLE_WORKSPACE_DIMENSIONS: {
      const double box[6] = {-80, -60, -60, 80, 60, 60};
      std::memcpy(out, box, sizeof(box));
      return;
    }
    case HD_MOTOR_TEMPERATURE:
      for (int i = 0; i < 3; ++i) out[i] = st.temperature;
      return;
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
    case HD_CURRENT_VELOCITY: {
      std::normal_distribution<double> noise(0.0, st.velocity_noise);
      for (int i = 0; i < 3; ++i) out[i] = velocity[i] + (st.velocity_noise > 0 ? noise(st.noise) : 0);
      return;
    }
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
  if (what == HD_UPDATE_RATE) {
    *out = st.rate;
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
  st.frame_forced = true;
}

FAKEHD_EXPORT void hdBeginFrame(HHD) {
  State& st = S();
  if (st.in_frame) {
    ++st.stats.frame_errors;
    Push(HD_ILLEGAL_BEGIN);
  }
  st.in_frame = true;
  st.frame_forced = false;
  const bool holding = st.force[0] != 0.0 || st.force[1] != 0.0 || st.force[2] != 0.0;
  if (st.has_last_end && holding && ServoTime() - st.last_end > st.watchdog) {
    // The host stopped updating the force: the device's watchdog cuts the motors.
    st.force[0] = st.force[1] = st.force[2] = 0.0;
    ++st.stats.watchdog_faults;
    Push(HD_FORCE_ERROR, 2);
  }
}

FAKEHD_EXPORT void hdEndFrame(HHD) {
  State& st = S();
  if (!st.in_frame) {
    ++st.stats.frame_errors;
    Push(HD_ILLEGAL_END);
    return;
  }
  st.in_frame = false;
  st.last_end = ServoTime();
  st.has_last_end = true;
  ++st.stats.frames;
  const double norm =
      std::sqrt(st.force[0] * st.force[0] + st.force[1] * st.force[1] + st.force[2] * st.force[2]);
  // Motors: hot from the scenario's frame on; cool towards ambient while holding no force.
  if (st.warm_frame > 0 && st.stats.frames == st.warm_frame) st.temperature = 1.0;
  if (norm == 0.0 && st.cool_seconds > 0.0) {
    st.temperature =
        st.ambient + (st.temperature - st.ambient) * std::exp(-1.0 / (st.rate * st.cool_seconds));
  }
  if (st.temperature >= kHotTemperature && norm > 0.0) {
    ++st.stats.hot_forced_frames;
    ++st.stats.warm_errors;
    st.force[0] = st.force[1] = st.force[2] = 0.0;  // the driver will not drive hot motors
    Push(HD_WARM_MOTORS);
  }
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
  if (st.stats.frames == st.velocity_error_frame) {
    st.stats.velocity_error_frame = st.stats.frames;
    st.force[0] = st.force[1] = st.force[2] = 0.0;  // the driver cuts the force itself
    Push(HD_EXCEEDED_MAX_VELOCITY, 3);
  }
}

FAKEHD_EXPORT HDSchedulerHandle hdScheduleAsynchronous(HDSchedulerCallback callback, void* data,
                                                       HDushort) {
  std::lock_guard<std::mutex> lock(S().mutex);
  const HDSchedulerHandle handle = S().next_handle++;
  S().scheduled.push_back(Scheduled{handle, callback, data, false, nullptr});
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

// Runs `callback` on the servo thread until it returns DONE, and waits for that.
FAKEHD_EXPORT void hdScheduleSynchronous(HDSchedulerCallback callback, void* data, HDushort) {
  State& st = S();
  if (!st.running) {
    Push(HD_INVALID_OPERATION);  // nothing would ever run it
    return;
  }
  bool finished = false;
  std::unique_lock<std::mutex> lock(st.mutex);
  st.scheduled.push_back(Scheduled{st.next_handle++, callback, data, true, &finished});
  st.finished.wait(lock, [&] { return finished; });
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
    const timespec start = Monotonic();
    timespec next = start;
    const long period_ns = 1000000000L / std::max(1, st.rate);
    std::vector<Scheduled> batch;
    while (!st.stop.load()) {
      {
        std::lock_guard<std::mutex> lock(st.mutex);
        batch = st.scheduled;
      }
      for (const Scheduled& s : batch) {
        if (s.callback(s.data) != HD_CALLBACK_DONE) continue;
        std::lock_guard<std::mutex> lock(st.mutex);
        auto& list = st.scheduled;
        for (auto it = list.begin(); it != list.end(); ++it) {
          if (it->handle == s.handle) {
            list.erase(it);
            break;
          }
        }
        if (s.synchronous) {
          *s.finished = true;
          st.finished.notify_all();
        }
      }
      st.servo_periods.fetch_add(1, std::memory_order_acq_rel);
      next.tv_nsec += period_ns;
      if (next.tv_nsec >= 1000000000) {
        next.tv_nsec -= 1000000000;
        ++next.tv_sec;
      }
      const timespec now = Monotonic();
      if (Seconds(next, now) > period_ns * 1e-9) {
        ++st.stats.late_frames;
        next = now;  // a servo loop that fell behind skips ticks rather than bursting
      } else {
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr);
      }
    }
    st.stats.servo_seconds = Seconds(start, Monotonic());
  });
  st.servo_id = st.servo.get_id();
}

FAKEHD_EXPORT void hdStopScheduler() {
  State& st = S();
  if (!st.running) return;
  st.stop.store(true);
  st.servo.join();
  st.running = false;
  // Synchronous calls still waiting would never run.
  std::lock_guard<std::mutex> lock(st.mutex);
  for (const Scheduled& s : st.scheduled) {
    if (s.synchronous) *s.finished = true;
  }
  st.scheduled.clear();
  st.finished.notify_all();
}

FAKEHD_EXPORT void fakehd_stats(FakeHdStats* out) { *out = S().stats; }

// The optional entry point through which a simulated HD library gives the plugin its clock
// (devices/phantom/phantom_hd_library.h).
FAKEHD_EXPORT double fitfeel_hd_device_time() { return ServoTime(); }
