#include "devices/phantom/phantom_device.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"

namespace fitfeel::phantom {
namespace {

constexpr double kMillimetre = 1e-3;
// After a force error the driver has cut the motors; sending zero for 100 ms lets it (and the hand)
// settle before forces come back, instead of hitting the same limit again at once.
constexpr int kRecoverTicks = 100;
// How long RunServoLoop waits for the first servo tick before declaring the scheduler dead.
constexpr double kFirstTickTimeout = 2.0;  // s

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

PhantomDevice::~PhantomDevice() { DoStop(); }

void PhantomDevice::Configure(const PhantomSettings& settings) {
  if (!settings.model.empty() && !settings.spec) LookupDeviceSpec(settings.model);
  if (settings.spec) ValidateDeviceSpec(*settings.spec);
  settings_ = settings;
  spec_ = settings.spec ? *settings.spec : FindDeviceSpec(settings.model).value_or(DeviceSpec{});
}

void PhantomDevice::CheckError(const char* what) {
  const HDErrorInfo error = hd_.hdGetError();
  if (error.errorCode == HD_SUCCESS) return;
  // Drain the rest of the stack so that the next check starts clean.
  for (int i = 0; i < 64 && hd_.hdGetError().errorCode != HD_SUCCESS; ++i) {
  }
  throw UserError(std::string("OpenHaptics ") + what + " failed: " + hd::DescribeError(hd_, error) +
                  " (library " + hd_.path + ")");
}

void PhantomDevice::Calibrate() {
  HDenum status = hd_.hdCheckCalibration();
  CheckError("hdCheckCalibration");
  if (status == HD_CALIBRATION_OK) return;
  HDint styles = 0;
  hd_.hdGetIntegerv(HD_CALIBRATION_STYLE, &styles);
  CheckError("hdGetIntegerv(HD_CALIBRATION_STYLE)");
  if (status == HD_CALIBRATION_NEEDS_MANUAL_INPUT) {
    throw UserError(
        "the haptic device needs manual calibration: put the stylus in its inkwell (or run the "
        "vendor's Touch Setup / Diagnostic calibration) and start again");
  }
  if (status != HD_CALIBRATION_NEEDS_UPDATE) {
    throw UserError("OpenHaptics hdCheckCalibration returned an unknown status " +
                    std::to_string(status));
  }
  if (!settings_.auto_calibrate) {
    throw UserError("the haptic device's calibration needs an update and auto_calibrate is off");
  }
  // Automatic and inkwell styles update without the user; encoder reset needs the arm held in its
  // reset pose, which a run cannot ask for.
  HDenum style = 0;
  if (styles & HD_CALIBRATION_AUTO) {
    style = HD_CALIBRATION_AUTO;
  } else if (styles & HD_CALIBRATION_INKWELL) {
    style = HD_CALIBRATION_INKWELL;
  } else {
    throw UserError(
        "the haptic device needs an encoder-reset calibration: hold it in its reset position and "
        "run the vendor's calibration, then start again");
  }
  hd_.hdUpdateCalibration(style);
  CheckError("hdUpdateCalibration");
  status = hd_.hdCheckCalibration();
  CheckError("hdCheckCalibration");
  if (status != HD_CALIBRATION_OK) {
    throw UserError(
        "the haptic device is still not calibrated after hdUpdateCalibration; put the "
        "stylus in its inkwell and start again");
  }
}

DeviceSpec PhantomDevice::ResolveSpec() {
  HDstring model = hd_.hdGetString(HD_DEVICE_MODEL_TYPE);
  CheckError("hdGetString(HD_DEVICE_MODEL_TYPE)");
  diagnostics_.hd_model = model != nullptr ? model : "";
  double max_force = 0.0, max_continuous = 0.0, stiffness = 0.0, damping = 0.0;
  double workspace[6] = {0, 0, 0, 0, 0, 0};
  hd_.hdGetDoublev(HD_NOMINAL_MAX_FORCE, &max_force);
  CheckError("hdGetDoublev(HD_NOMINAL_MAX_FORCE)");
  hd_.hdGetDoublev(HD_NOMINAL_MAX_CONTINUOUS_FORCE, &max_continuous);
  CheckError("hdGetDoublev(HD_NOMINAL_MAX_CONTINUOUS_FORCE)");
  hd_.hdGetDoublev(HD_NOMINAL_MAX_STIFFNESS, &stiffness);
  CheckError("hdGetDoublev(HD_NOMINAL_MAX_STIFFNESS)");
  hd_.hdGetDoublev(HD_NOMINAL_MAX_DAMPING, &damping);
  CheckError("hdGetDoublev(HD_NOMINAL_MAX_DAMPING)");
  hd_.hdGetDoublev(HD_USABLE_WORKSPACE_DIMENSIONS, workspace);
  CheckError("hdGetDoublev(HD_USABLE_WORKSPACE_DIMENSIONS)");
  diagnostics_.hd_max_force = max_force;
  diagnostics_.hd_max_continuous_force = max_continuous;

  DeviceSpec spec;
  if (settings_.spec) {
    spec = *settings_.spec;
  } else if (auto known = FindDeviceSpec(settings_.model)) {
    spec = *known;
  } else if (auto reported = FindDeviceSpec(diagnostics_.hd_model)) {
    spec = *reported;
  } else {
    // A model the table does not know: the driver's nominal values (stiffness and damping are
    // per millimetre in HD).
    spec.model = diagnostics_.hd_model.empty() ? "OpenHaptics device" : diagnostics_.hd_model;
    spec.max_force = max_force;
    spec.max_continuous_force = max_continuous;
    spec.max_stiffness = stiffness * 1000.0;
    spec.damping = damping * 1000.0;
    for (int i = 0; i < 3; ++i) spec.workspace[i] = (workspace[i + 3] - workspace[i]) * kMillimetre;
    spec.native_rate = 1000.0;
  }
  // The driver knows this unit: never promise more force than it does.
  if (max_force > 0.0) spec.max_force = std::min(spec.max_force, max_force);
  if (max_continuous > 0.0) {
    spec.max_continuous_force = std::min(spec.max_continuous_force, max_continuous);
  }
  spec.max_continuous_force = std::min(spec.max_continuous_force, spec.max_force);
  ValidateDeviceSpec(spec);
  return spec;
}

void PhantomDevice::DoStart(double) {
  DoStop();
  hd_ = hd::LoadLibrary();
  diagnostics_ = PhantomDiagnostics{};
  diagnostics_.library = hd_.path;
  const HHD handle = hd_.hdInitDevice(HD_DEFAULT_DEVICE);
  const HDErrorInfo error = hd_.hdGetError();
  if (error.errorCode != HD_SUCCESS || handle == HD_INVALID_HANDLE) {
    throw UserError("OpenHaptics hdInitDevice(HD_DEFAULT_DEVICE) failed: " +
                    (error.errorCode != HD_SUCCESS ? hd::DescribeError(hd_, error)
                                                   : std::string("invalid handle")) +
                    " (library " + hd_.path +
                    "); is the device connected, powered and configured (Touch Setup)?");
  }
  handle_ = handle;
  try {
    hd_.hdMakeCurrentDevice(handle_);
    CheckError("hdMakeCurrentDevice");
    hd_.hdEnable(HD_FORCE_OUTPUT);
    CheckError("hdEnable(HD_FORCE_OUTPUT)");
    // The driver's own clamp is a second net under ours.
    hd_.hdEnable(HD_MAX_FORCE_CLAMPING);
    CheckError("hdEnable(HD_MAX_FORCE_CLAMPING)");
    Calibrate();
    spec_ = ResolveSpec();
  } catch (...) {
    DoStop();
    throw;
  }
  state_ = DeviceState{};
  pending_force_.setZero();
}

void PhantomDevice::DoStop() noexcept {
  if (handle_ == HD_INVALID_HANDLE) return;
  hd_.hdDisableDevice(handle_);
  for (int i = 0; i < 64 && hd_.hdGetError().errorCode != HD_SUCCESS; ++i) {
  }
  handle_ = HD_INVALID_HANDLE;
}

void PhantomDevice::RunServoLoop(double duration, const std::function<bool(double)>& tick) {
  if (handle_ == HD_INVALID_HANDLE) {
    throw UserError("Phantom: RunServoLoop called before Start");
  }
  if (!(duration > 0.0) || !std::isfinite(duration)) {
    throw UserError("Phantom: servo run duration must be a positive number of seconds");
  }
  tick_ = &tick;
  duration_ = duration;
  start_time_ = -1.0;
  recover_ticks_ = 0;
  fatal_ = HDErrorInfo{HD_SUCCESS, 0, 0};
  done_.store(false, std::memory_order_release);
  ticks_.store(0, std::memory_order_relaxed);
  const HDSchedulerHandle scheduled =
      hd_.hdScheduleAsynchronous(&PhantomDevice::ServoCallback, this, HD_MAX_SCHEDULER_PRIORITY);
  CheckError("hdScheduleAsynchronous");
  hd_.hdStartScheduler();
  try {
    CheckError("hdStartScheduler");
  } catch (...) {
    hd_.hdUnschedule(scheduled);
    throw;
  }
  const double begin = Now();
  bool stalled = false;
  while (!done_.load(std::memory_order_acquire)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    const double waited = Now() - begin;
    // No tick at all, or a loop running far past its duration: the scheduler is not serving us.
    if ((ticks_.load(std::memory_order_relaxed) == 0 && waited > kFirstTickTimeout) ||
        waited > duration + kFirstTickTimeout + 10.0) {
      stalled = true;
      break;
    }
  }
  hd_.hdStopScheduler();
  hd_.hdUnschedule(scheduled);
  tick_ = nullptr;
  if (stalled) {
    throw UserError("OpenHaptics servo scheduler did not run the servo callback (library " +
                    hd_.path + ")");
  }
  if (fatal_.errorCode != HD_SUCCESS) {
    throw UserError("OpenHaptics servo loop stopped on " + hd::DescribeError(hd_, fatal_) +
                    " after " + std::to_string(diagnostics_.ticks) + " ticks");
  }
}

HDCallbackCode PhantomDevice::ServoCallback(void* self) {
  return static_cast<PhantomDevice*>(self)->Servo();
}

HDCallbackCode PhantomDevice::Servo() noexcept {
  if (tick_ == nullptr) return HD_CALLBACK_DONE;
  hd_.hdBeginFrame(handle_);
  double position[3], velocity[3], angular[3], transform[16];
  HDint buttons = 0;
  hd_.hdGetDoublev(HD_CURRENT_POSITION, position);
  hd_.hdGetDoublev(HD_CURRENT_TRANSFORM, transform);
  hd_.hdGetDoublev(HD_CURRENT_VELOCITY, velocity);
  hd_.hdGetDoublev(HD_CURRENT_ANGULAR_VELOCITY, angular);
  hd_.hdGetIntegerv(HD_CURRENT_BUTTONS, &buttons);
  const double now = Now();
  if (start_time_ < 0.0) start_time_ = now;
  const double time = now - start_time_;

  state_.time = time;
  state_.position = Eigen::Vector3d(position[0], position[1], position[2]) * kMillimetre;
  state_.velocity = Eigen::Vector3d(velocity[0], velocity[1], velocity[2]) * kMillimetre;
  state_.angular_velocity = Eigen::Vector3d(angular[0], angular[1], angular[2]);
  Eigen::Matrix3d rotation;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) rotation(r, c) = transform[4 * c + r];  // column-major
  }
  const Eigen::Quaterniond orientation(rotation);
  if (orientation.coeffs().allFinite()) state_.orientation = orientation.normalized();
  state_.buttons = static_cast<std::uint32_t>(buttons);

  pending_force_.setZero();
  bool keep = false;
  try {
    keep = (*tick_)(time);
  } catch (...) {
    keep = false;  // a tick must not throw; stop cleanly with zero force
    pending_force_.setZero();
  }

  Eigen::Vector3d force = pending_force_.allFinite() ? pending_force_ : Eigen::Vector3d::Zero();
  if (recover_ticks_ > 0) {
    --recover_ticks_;
    ++diagnostics_.zeroed_ticks;
    force.setZero();
  }
  const double limit = diagnostics_.hd_max_force > 0.0
                           ? std::min(diagnostics_.hd_max_force, spec_.max_force)
                           : spec_.max_force;
  const double norm = force.norm();
  if (norm > limit) {
    ++diagnostics_.clamped_writes;
    force *= limit / norm * (1.0 - 1e-12);
  }
  if (!keep || time >= duration_) {
    keep = false;
    force.setZero();  // the last frame leaves the device without force
  }
  const double out[3] = {force.x(), force.y(), force.z()};
  hd_.hdSetDoublev(HD_CURRENT_FORCE, out);
  hd_.hdEndFrame(handle_);
  state_.delivered.force = force;
  state_.delivered.torque.setZero();
  diagnostics_.max_force_sent = std::max(diagnostics_.max_force_sent, force.norm());
  ticks_.fetch_add(1, std::memory_order_relaxed);
  ++diagnostics_.ticks;

  for (int i = 0; i < 16; ++i) {
    const HDErrorInfo error = hd_.hdGetError();
    if (error.errorCode == HD_SUCCESS) break;
    diagnostics_.last_error = error.errorCode;
    if (hd::IsForceError(error.errorCode)) {
      ++diagnostics_.force_errors;
      recover_ticks_ = kRecoverTicks;
    } else if (fatal_.errorCode == HD_SUCCESS) {
      fatal_ = error;
      keep = false;
    }
  }
  if (!keep) {
    done_.store(true, std::memory_order_release);
    return HD_CALLBACK_DONE;
  }
  return HD_CALLBACK_CONTINUE;
}

void PhantomDevice::DoRead(double, DeviceState* out) noexcept { *out = state_; }

void PhantomDevice::DoWrite(const Wrench& wrench) noexcept { pending_force_ = wrench.force; }

PhantomDiagnostics PhantomDevice::diagnostics() const { return diagnostics_; }

}  // namespace fitfeel::phantom
