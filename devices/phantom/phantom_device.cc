#include "devices/phantom/phantom_device.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"

namespace fitfeel::phantom {
namespace {

constexpr double kMillimetre = 1e-3;
// How long RunServoLoop waits for the first servo tick before declaring the scheduler dead.
constexpr double kFirstTickTimeout = 2.0;  // s
// How often the calibration status is polled while the user calibrates by hand.
constexpr auto kCalibrationPoll = std::chrono::milliseconds(100);

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The device's time: a simulated device's own clock where its library gives one, else the host's.
double DeviceNow(const hd::Library& hd) {
  return hd.fitfeel_hd_device_time != nullptr ? hd.fitfeel_hd_device_time() : Now();
}

// The part's axes in the stylus frame. OpenHaptics puts the gimbal's z axis along the stylus,
// pointing from the tip back towards the hand (the third column of HD_CURRENT_TRANSFORM), so the
// part's leading direction (its y) is the stylus's -z; x is shared and z = x cross y = the
// stylus's y.
const Eigen::Matrix3d& PartInStylus() {
  static const Eigen::Matrix3d m = (Eigen::Matrix3d() << 1, 0, 0, 0, 0, 1, 0, -1, 0).finished();
  return m;
}

std::string SetUpHints() {
  return " Check that the device is connected and powered, that its driver is configured (Touch "
         "Setup / Geomagic Touch Setup names the device; the device name in the scenario must "
         "match), and that your user may open its port (on Linux, the device node such as "
         "/dev/ttyACM0 belongs to the 'dialout' group: add yourself to it and log in again).";
}

// The least damping a device that renders spec.max_stiffness stably at its rate must have
// (Colgate & Schenkel: b > K T / 2), used unless the scenario gives a measured one (damping > 0 in
// its spec). It is a bound inferred from the stiffness limit, so the passivity observer never
// credits it.
DeviceSpec WithHardwareDamping(DeviceSpec spec, bool measured) {
  if (!measured && spec.max_stiffness > 0.0 && spec.native_rate > 0.0) {
    spec.damping = spec.max_stiffness / spec.native_rate / 2.0;
  }
  spec.credit_damping = false;
  return spec;
}

}  // namespace

PhantomDevice::~PhantomDevice() { DoStop(); }

void PhantomDevice::Configure(const PhantomSettings& settings) {
  if (!settings.model.empty() && !settings.spec) LookupDeviceSpec(settings.model);
  const bool measured = settings.spec && settings.spec->damping > 0.0;
  if (settings.spec) ValidateDeviceSpec(WithHardwareDamping(*settings.spec, measured));
  const Eigen::Matrix3d& axes = settings.frame.axes;
  if (!axes.allFinite() || !(axes * axes.transpose()).isIdentity(1e-12) ||
      !(std::abs(axes.determinant() - 1.0) < 1e-12)) {
    throw UserError("Phantom: frame.axes must be a rotation (a signed permutation of x, y, z)");
  }
  if (!settings.frame.origin.allFinite() || !settings.frame.home.allFinite()) {
    throw UserError("Phantom: frame.origin and frame.home must be finite");
  }
  if (!(settings.calibration_timeout >= 0.0) || !std::isfinite(settings.calibration_timeout)) {
    throw UserError("Phantom: calibration_timeout must be a finite time >= 0");
  }
  if (!(settings.ramp_time >= 0.0) || !std::isfinite(settings.ramp_time) ||
      !(settings.fault_window > 0.0) || !std::isfinite(settings.fault_window)) {
    throw UserError("Phantom: ramp_time must be >= 0 and fault_window > 0, both finite");
  }
  if (settings.max_faults < 1 || settings.max_faults > static_cast<int>(fault_times_.size())) {
    throw UserError("Phantom: max_faults must be in [1, " + std::to_string(fault_times_.size()) +
                    "]");
  }
  if (!(settings.derate_temperature > 0.0 && settings.derate_temperature < 1.0)) {
    throw UserError("Phantom: derate_temperature must be in (0, 1)");
  }
  if (!(settings.rate_tolerance > 0.0 && settings.rate_tolerance < 1.0)) {
    throw UserError("Phantom: rate_tolerance must be in (0, 1)");
  }
  settings_ = settings;
  // Until Start reads the driver, the table's (or the scenario's) limits.
  spec_ = settings.spec ? *settings.spec : FindDeviceSpec(settings.model).value_or(DeviceSpec{});
  spec_ = WithHardwareDamping(spec_, measured);
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

namespace {

struct CalibrationCall {
  const hd::Library* hd;
  HHD handle;
  HDenum status;
  HDenum style;  // 0: only check
};

// Calibration runs in the scheduler, as the SDK requires: a synchronous callback that checks the
// status inside a frame and, when asked to, updates it.
HDCallbackCode CalibrationCallback(void* data) {
  auto* call = static_cast<CalibrationCall*>(data);
  call->hd->hdBeginFrame(call->handle);
  if (call->style != 0 && call->hd->hdCheckCalibration() == HD_CALIBRATION_NEEDS_UPDATE) {
    call->hd->hdUpdateCalibration(call->style);
  }
  call->status = call->hd->hdCheckCalibration();
  call->hd->hdEndFrame(call->handle);
  return HD_CALLBACK_DONE;
}

}  // namespace

HDenum PhantomDevice::CalibrationStatus() {
  CalibrationCall call{&hd_, handle_, 0, 0};
  hd_.hdScheduleSynchronous(&CalibrationCallback, &call, HD_MAX_SCHEDULER_PRIORITY);
  CheckError("hdCheckCalibration (in the scheduler)");
  return call.status;
}

void PhantomDevice::Calibrate() {
  HDenum status = CalibrationStatus();
  diagnostics_.calibration = "ok";
  if (status == HD_CALIBRATION_OK) return;
  if (status == HD_CALIBRATION_NEEDS_MANUAL_INPUT) {
    // The SDK's way: prompt the user and poll until the status turns ok.
    if (settings_.calibration_timeout > 0.0) {
      std::fprintf(stderr,
                   "fitfeel: the haptic device needs calibrating by hand: put the stylus in its "
                   "inkwell (or move each joint through its range); waiting up to %.1f s...\n",
                   settings_.calibration_timeout);
      const double begin = DeviceNow(hd_);
      while (status == HD_CALIBRATION_NEEDS_MANUAL_INPUT &&
             DeviceNow(hd_) - begin < settings_.calibration_timeout) {
        std::this_thread::sleep_for(kCalibrationPoll);
        status = CalibrationStatus();
      }
      diagnostics_.calibration_wait = DeviceNow(hd_) - begin;
    }
    if (status == HD_CALIBRATION_NEEDS_MANUAL_INPUT) {
      throw UserError(
          "the haptic device needs manual calibration and did not get it within "
          "calibration_timeout: put the stylus in its inkwell (or run the vendor's Touch Setup / "
          "Diagnostic calibration) and start again");
    }
    diagnostics_.calibration = "manual";
    if (status == HD_CALIBRATION_OK) return;
  }
  if (status != HD_CALIBRATION_NEEDS_UPDATE) {
    throw UserError("OpenHaptics hdCheckCalibration returned an unknown status " +
                    std::to_string(status));
  }
  if (!settings_.auto_calibrate) {
    throw UserError("the haptic device's calibration needs an update and auto_calibrate is off");
  }
  HDint styles = 0;
  hd_.hdGetIntegerv(HD_CALIBRATION_STYLE, &styles);
  CheckError("hdGetIntegerv(HD_CALIBRATION_STYLE)");
  // Automatic and inkwell styles update without the user; encoder reset needs the arm held in its
  // reset pose, which a run cannot ask for.
  HDenum style = 0;
  if (styles & HD_CALIBRATION_AUTO) {
    style = HD_CALIBRATION_AUTO;
    diagnostics_.calibration = "updated (auto)";
  } else if (styles & HD_CALIBRATION_INKWELL) {
    style = HD_CALIBRATION_INKWELL;
    diagnostics_.calibration = "updated (inkwell)";
  } else {
    throw UserError(
        "the haptic device needs an encoder-reset calibration: hold it in its reset position and "
        "run the vendor's calibration, then start again");
  }
  CalibrationCall call{&hd_, handle_, 0, style};
  hd_.hdScheduleSynchronous(&CalibrationCallback, &call, HD_MAX_SCHEDULER_PRIORITY);
  CheckError("hdUpdateCalibration (in the scheduler)");
  ++diagnostics_.calibration_updates;
  if (call.status != HD_CALIBRATION_OK) {
    throw UserError(
        "the haptic device is still not calibrated after hdUpdateCalibration; put the "
        "stylus in its inkwell and start again");
  }
}

DeviceSpec PhantomDevice::ResolveSpec(double period) {
  HDstring model = hd_.hdGetString(HD_DEVICE_MODEL_TYPE);
  CheckError("hdGetString(HD_DEVICE_MODEL_TYPE)");
  diagnostics_.hd_model = model != nullptr ? model : "";
  double max_force = 0.0, max_continuous = 0.0, stiffness = 0.0;
  double workspace[6] = {0, 0, 0, 0, 0, 0};
  HDint rate = 0;
  hd_.hdGetDoublev(HD_NOMINAL_MAX_FORCE, &max_force);
  CheckError("hdGetDoublev(HD_NOMINAL_MAX_FORCE)");
  hd_.hdGetDoublev(HD_NOMINAL_MAX_CONTINUOUS_FORCE, &max_continuous);
  CheckError("hdGetDoublev(HD_NOMINAL_MAX_CONTINUOUS_FORCE)");
  hd_.hdGetDoublev(HD_NOMINAL_MAX_STIFFNESS, &stiffness);
  CheckError("hdGetDoublev(HD_NOMINAL_MAX_STIFFNESS)");
  hd_.hdGetDoublev(HD_USABLE_WORKSPACE_DIMENSIONS, workspace);
  CheckError("hdGetDoublev(HD_USABLE_WORKSPACE_DIMENSIONS)");
  hd_.hdGetIntegerv(HD_UPDATE_RATE, &rate);
  CheckError("hdGetIntegerv(HD_UPDATE_RATE)");
  diagnostics_.hd_max_force = max_force;
  diagnostics_.hd_max_continuous_force = max_continuous;
  diagnostics_.hd_max_stiffness = stiffness * 1000.0;  // HD gives N/mm
  diagnostics_.update_rate = rate;

  // The servo loop runs at the driver's rate whatever the scenario says: a scene prepared for
  // another rate would integrate and couple with the wrong period.
  const double run_rate = 1.0 / period;
  if (!(rate > 0) || std::abs(rate - run_rate) > settings_.rate_tolerance * run_rate) {
    throw UserError("the haptic device's servo loop runs at " + std::to_string(rate) +
                    " Hz (HD_UPDATE_RATE) but run.rate is " + std::to_string(std::lround(run_rate)) +
                    " Hz: set run.rate to the device's rate, or change the device's rate in its "
                    "driver set-up");
  }

  DeviceSpec spec;
  const bool measured_damping = settings_.spec.has_value() && settings_.spec->damping > 0.0;
  if (settings_.spec) {
    spec = *settings_.spec;
  } else if (auto known = FindDeviceSpec(settings_.model)) {
    spec = *known;
  } else if (auto reported = FindDeviceSpec(diagnostics_.hd_model)) {
    spec = *reported;
  } else {
    spec.model = diagnostics_.hd_model.empty() ? "OpenHaptics device" : diagnostics_.hd_model;
    spec.max_force = max_force;
    spec.max_continuous_force = max_continuous;
    spec.max_stiffness = diagnostics_.hd_max_stiffness;
    for (int i = 0; i < 3; ++i) spec.workspace[i] = (workspace[i + 3] - workspace[i]) * kMillimetre;
  }
  // The driver knows this unit: never promise more force or stiffness than it does.
  if (max_force > 0.0) spec.max_force = std::min(spec.max_force, max_force);
  if (max_continuous > 0.0) {
    spec.max_continuous_force = std::min(spec.max_continuous_force, max_continuous);
  }
  spec.max_continuous_force = std::min(spec.max_continuous_force, spec.max_force);
  if (diagnostics_.hd_max_stiffness > 0.0) {
    spec.max_stiffness = std::min(spec.max_stiffness, diagnostics_.hd_max_stiffness);
  }
  spec.native_rate = rate;
  spec = WithHardwareDamping(spec, measured_damping);
  ValidateDeviceSpec(spec);
  return spec;
}

void PhantomDevice::DoStart(double period) {
  DoStop();
  hd_ = hd::LoadLibrary();
  diagnostics_ = PhantomDiagnostics{};
  diagnostics_.library = hd_.path;
  const char* name = settings_.device_name.empty() ? HD_DEFAULT_DEVICE
                                                   : settings_.device_name.c_str();
  const std::string who =
      settings_.device_name.empty() ? "HD_DEFAULT_DEVICE" : "\"" + settings_.device_name + "\"";
  const HHD handle = hd_.hdInitDevice(name);
  const HDErrorInfo error = hd_.hdGetError();
  if (error.errorCode != HD_SUCCESS || handle == HD_INVALID_HANDLE) {
    for (int i = 0; i < 64 && hd_.hdGetError().errorCode != HD_SUCCESS; ++i) {
    }
    throw UserError("OpenHaptics hdInitDevice(" + who + ") failed: " +
                    (error.errorCode != HD_SUCCESS ? hd::DescribeError(hd_, error)
                                                   : std::string("invalid handle")) +
                    " (library " + hd_.path + ")." + SetUpHints());
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
    hd_.hdStartScheduler();
    CheckError("hdStartScheduler");
    scheduler_running_ = true;
    Calibrate();
    spec_ = ResolveSpec(period);
  } catch (...) {
    DoStop();
    throw;
  }
  state_ = DeviceState{};
  pending_force_.setZero();
  origin_ = settings_.frame.origin;
}

void PhantomDevice::DoStop() noexcept {
  if (handle_ == HD_INVALID_HANDLE) return;
  // The SDK's order: stop the scheduler, then disable the device.
  if (scheduler_running_) hd_.hdStopScheduler();
  scheduler_running_ = false;
  hd_.hdDisableDevice(handle_);
  for (int i = 0; i < 64 && hd_.hdGetError().errorCode != HD_SUCCESS; ++i) {
  }
  handle_ = HD_INVALID_HANDLE;
}

void PhantomDevice::DoRunServoLoop(double duration, const std::function<bool(double)>& tick) {
  if (handle_ == HD_INVALID_HANDLE || !scheduler_running_) {
    throw UserError("Phantom: RunServoLoop called before Start");
  }
  if (!(duration > 0.0) || !std::isfinite(duration)) {
    throw UserError("Phantom: servo run duration must be a positive number of seconds");
  }
  tick_ = &tick;
  duration_ = duration;
  start_time_ = -1.0;
  last_time_ = 0.0;
  gain_ = 1.0;
  warm_ = false;
  fault_count_ = 0;
  last_buttons_ = 0;
  fatal_ = HDErrorInfo{HD_SUCCESS, 0, 0};
  done_.store(false, std::memory_order_release);
  ticks_.store(0, std::memory_order_relaxed);
  const HDSchedulerHandle scheduled =
      hd_.hdScheduleAsynchronous(&PhantomDevice::ServoCallback, this, HD_MAX_SCHEDULER_PRIORITY);
  CheckError("hdScheduleAsynchronous");
  // The host's clock even where the device has its own: a scheduler that never ticks stops the
  // device's clock too.
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
  hd_.hdUnschedule(scheduled);
  tick_ = nullptr;
  if (stalled) {
    throw UserError("OpenHaptics servo scheduler did not run the servo callback (library " +
                    hd_.path + ")");
  }
  if (fatal_.errorCode != HD_SUCCESS) {
    throw UserError("OpenHaptics servo loop stopped on " + hd::DescribeError(hd_, fatal_) +
                    " after " + std::to_string(diagnostics_.ticks) + " ticks." + SetUpHints());
  }
}

HDCallbackCode PhantomDevice::ServoCallback(void* self) {
  return static_cast<PhantomDevice*>(self)->Servo();
}

bool PhantomDevice::CountFault(double time) noexcept {
  const int n = settings_.max_faults;
  fault_times_[static_cast<std::size_t>(fault_count_ % n)] = time;
  ++fault_count_;
  if (fault_count_ < n) return false;
  // The oldest of the last n faults is the one the ring overwrites next.
  const double oldest = fault_times_[static_cast<std::size_t>(fault_count_ % n)];
  return time - oldest <= settings_.fault_window;
}

double PhantomDevice::FaultGain(double dt, const double* temperature) noexcept {
  double hottest = 0.0;
  for (int i = 0; i < hd::kMaxMotors; ++i) {
    if (std::isfinite(temperature[i])) hottest = std::max(hottest, temperature[i]);
  }
  diagnostics_.max_motor_temperature = std::max(diagnostics_.max_motor_temperature, hottest);
  const double cool = settings_.derate_temperature;
  if (warm_) {
    if (hottest >= cool) {
      ++diagnostics_.zeroed_ticks;
      return 0.0;
    }
    warm_ = false;
    gain_ = 0.0;  // cool again: come back through the ramp
  }
  double factor = 1.0;
  if (gain_ < 1.0) {
    gain_ = settings_.ramp_time > 0.0 ? std::min(1.0, gain_ + dt / settings_.ramp_time) : 1.0;
    factor = gain_;
    if (factor > 0.0) {
      ++diagnostics_.ramped_ticks;
    } else {
      ++diagnostics_.zeroed_ticks;
    }
  }
  if (hottest > cool) {
    factor *= std::clamp((1.0 - hottest) / (1.0 - cool), 0.0, 1.0);
    ++diagnostics_.derated_ticks;
  }
  return factor;
}

HDCallbackCode PhantomDevice::Servo() noexcept {
  if (tick_ == nullptr) return HD_CALLBACK_DONE;
  hd_.hdBeginFrame(handle_);
  double position[3], velocity[3], angular[3], transform[16];
  double temperature[hd::kMaxMotors] = {0, 0, 0, 0, 0, 0};
  HDint buttons = 0;
  hd_.hdGetDoublev(HD_CURRENT_POSITION, position);
  hd_.hdGetDoublev(HD_CURRENT_TRANSFORM, transform);
  hd_.hdGetDoublev(HD_CURRENT_VELOCITY, velocity);
  hd_.hdGetDoublev(HD_CURRENT_ANGULAR_VELOCITY, angular);
  hd_.hdGetIntegerv(HD_CURRENT_BUTTONS, &buttons);
  hd_.hdGetDoublev(HD_MOTOR_TEMPERATURE, temperature);
  const double now = DeviceNow(hd_);
  if (start_time_ < 0.0) start_time_ = now;
  const double time = now - start_time_;
  const double dt = ticks_.load(std::memory_order_relaxed) > 0 ? time - last_time_ : 0.0;
  last_time_ = time;
  if (dt > 0.0) {
    const double n = static_cast<double>(diagnostics_.ticks);
    diagnostics_.mean_period = (diagnostics_.mean_period * (n - 1.0) + dt) / n;
    diagnostics_.max_period = std::max(diagnostics_.max_period, dt);
  }

  const Eigen::Matrix3d& axes = settings_.frame.axes;
  const Eigen::Vector3d device_position =
      Eigen::Vector3d(position[0], position[1], position[2]) * kMillimetre;
  const auto pressed = static_cast<std::uint32_t>(buttons);
  const std::uint32_t zero = settings_.frame.zero_button;
  if (zero != 0 && (pressed & zero) != 0 && (last_buttons_ & zero) == 0) {
    origin_ = device_position - axes.transpose() * settings_.frame.home;
    ++diagnostics_.zeroings;
  }
  last_buttons_ = pressed;
  state_.time = time;
  state_.position = axes * (device_position - origin_);
  state_.velocity = axes * Eigen::Vector3d(velocity[0], velocity[1], velocity[2]) * kMillimetre;
  state_.angular_velocity = axes * Eigen::Vector3d(angular[0], angular[1], angular[2]);
  Eigen::Matrix3d stylus;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) stylus(r, c) = transform[4 * c + r];  // column-major
  }
  const Eigen::Quaterniond orientation(axes * stylus * PartInStylus());
  if (orientation.coeffs().allFinite()) state_.orientation = orientation.normalized();
  state_.buttons = pressed;

  pending_force_.setZero();
  bool keep = false;
  try {
    keep = (*tick_)(time);
  } catch (...) {
    keep = false;  // a tick must not throw; stop cleanly with zero force
    pending_force_.setZero();
  }

  Eigen::Vector3d force = pending_force_.allFinite() ? pending_force_ : Eigen::Vector3d::Zero();
  force *= FaultGain(dt, temperature);
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
    force.setZero();  // the device keeps the last force it was sent: the last one is zero
  }
  const Eigen::Vector3d device_force = axes.transpose() * force;
  const double out[3] = {device_force.x(), device_force.y(), device_force.z()};
  hd_.hdSetDoublev(HD_CURRENT_FORCE, out);
  hd_.hdEndFrame(handle_);
  state_.delivered.force = force;
  state_.delivered.torque.setZero();
  diagnostics_.max_force_sent = std::max(diagnostics_.max_force_sent, force.norm());
  ticks_.fetch_add(1, std::memory_order_relaxed);
  ++diagnostics_.ticks;

  bool repeated = false;
  for (int i = 0; i < 16; ++i) {
    const HDErrorInfo error = hd_.hdGetError();
    if (error.errorCode == HD_SUCCESS) break;
    diagnostics_.last_error = error.errorCode;
    if (error.errorCode == HD_WARM_MOTORS) {
      ++diagnostics_.warm_motor_errors;
      warm_ = true;
      repeated |= CountFault(time);
    } else if (error.errorCode == HD_EXCEEDED_MAX_VELOCITY) {
      ++diagnostics_.velocity_errors;
      gain_ = 0.0;
      repeated |= CountFault(time);
    } else if (hd::IsForceError(error.errorCode)) {
      ++diagnostics_.force_errors;
      gain_ = 0.0;
      repeated |= CountFault(time);
    } else if (fatal_.errorCode == HD_SUCCESS) {
      fatal_ = error;
      keep = false;
    }
  }
  if (repeated && keep) {
    // The device keeps faulting: end the run rather than render on and off. The last force it
    // holds is from this frame, so one more frame sends zero.
    diagnostics_.stopped_on_faults = true;
    hd_.hdBeginFrame(handle_);
    const double zero_force[3] = {0.0, 0.0, 0.0};
    hd_.hdSetDoublev(HD_CURRENT_FORCE, zero_force);
    hd_.hdEndFrame(handle_);
    for (int i = 0; i < 16 && hd_.hdGetError().errorCode != HD_SUCCESS; ++i) {
    }
    keep = false;
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

DeviceReport PhantomDevice::DoReport() const {
  const PhantomDiagnostics& d = diagnostics_;
  DeviceReport r;
  r.Set("model", d.hd_model)
      .Set("library", d.library)
      .Set("calibration", d.calibration)
      .Set("calibration_updates", d.calibration_updates)
      .Set("calibration_wait_s", d.calibration_wait)
      .Set("update_rate_Hz", d.update_rate)
      .Set("mean_period_s", d.mean_period)
      .Set("max_period_s", d.max_period)
      .Set("servo_ticks", d.ticks)
      .Set("force_errors", d.force_errors)
      .Set("velocity_errors", d.velocity_errors)
      .Set("warm_motor_errors", d.warm_motor_errors)
      .Set("zeroed_ticks", d.zeroed_ticks)
      .Set("ramped_ticks", d.ramped_ticks)
      .Set("derated_ticks", d.derated_ticks)
      .Set("clamped_writes", d.clamped_writes)
      .Set("zeroings", d.zeroings)
      .Set("max_motor_temperature", d.max_motor_temperature)
      .Set("max_force_sent_N", d.max_force_sent)
      .Set("stopped_on_faults", d.stopped_on_faults);
  return r;
}

}  // namespace fitfeel::phantom
