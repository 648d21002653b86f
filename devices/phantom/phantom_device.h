#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "devices/phantom/phantom_hd_library.h"
#include "framework/device/device.h"

namespace fitfeel::phantom {

// How the device's axes and origin map to the scene frame (y: the mating axis, pointing into the
// fixed part; the entrance at y = 0).
struct PhantomFrame {
  // Row i: scene axis i in device coordinates (a signed permutation, a proper rotation). Default
  // x, -z, y: the user pushes the part away from them, into the screen, along the scene's y.
  Eigen::Matrix3d axes = (Eigen::Matrix3d() << 1, 0, 0, 0, 0, -1, 0, 1, 0).finished();
  // Device point (m, device coordinates) that maps to the scene's origin. Default: 20 mm beyond
  // the workspace's centre, so the stylus held at the centre is 20 mm before the entrance.
  Eigen::Vector3d origin{0.0, 0.0, -0.020};
  // Buttons (HD_DEVICE_BUTTON_n bit mask, 0: none) whose press makes the stylus's current
  // position the scene point `home`; the origin follows.
  std::uint32_t zero_button = 0;
  Eigen::Vector3d home{0.0, -0.020, 0.0};  // m, scene frame
};

struct PhantomSettings {
  // Spec: `spec` if given, else the table entry for `model`, else the table entry for the model
  // the driver reports, else the driver's nominal values. Force and stiffness limits are then
  // lowered to the driver's nominal values where those are smaller.
  std::string model;
  std::optional<DeviceSpec> spec;
  // The device name given to hdInitDevice (as configured in Touch Setup); empty: the default.
  std::string device_name;
  // Run the driver's automatic calibration when it asks for an update.
  bool auto_calibrate = true;
  // How long the user is given to calibrate by hand (stylus into its inkwell) when asked, s.
  double calibration_timeout = 30.0;
  PhantomFrame frame;
  // Force error recovery. After a velocity or force error the force comes back over ramp_time;
  // max_faults faults within fault_window stop the run. Above derate_temperature (normalized
  // HD_MOTOR_TEMPERATURE: 1 is the driver's cut-off) the force falls linearly to zero at 1; after
  // HD_WARM_MOTORS the force stays off until every motor is below it again.
  double ramp_time = 0.25;  // s
  int max_faults = 5;
  double fault_window = 10.0;  // s
  double derate_temperature = 0.8;
  // Largest relative difference accepted between HD_UPDATE_RATE and the run's rate.
  double rate_tolerance = 0.05;
};

// What the servo loop saw, for the run summary and the tests.
struct PhantomDiagnostics {
  std::uint64_t ticks = 0;
  std::uint64_t force_errors = 0;       // HD_EXCEEDED_MAX_FORCE, _IMPULSE, HD_FORCE_ERROR
  std::uint64_t velocity_errors = 0;    // HD_EXCEEDED_MAX_VELOCITY
  std::uint64_t warm_motor_errors = 0;  // HD_WARM_MOTORS
  std::uint64_t zeroed_ticks = 0;       // ticks sent zero force while a fault lasted
  std::uint64_t ramped_ticks = 0;       // ticks sent a fraction of the force after one
  std::uint64_t derated_ticks = 0;      // ticks whose force the motor temperature lowered
  std::uint64_t clamped_writes = 0;     // writes above the driver's nominal max force
  std::uint64_t zeroings = 0;           // presses of the zero button
  std::uint32_t last_error = 0;         // HD_ code of the last error seen (0: none)
  bool stopped_on_faults = false;       // max_faults within fault_window ended the run
  double max_force_sent = 0.0;          // N
  double max_motor_temperature = 0.0;   // normalized
  double update_rate = 0.0;             // HD_UPDATE_RATE, Hz
  double mean_period = 0.0;             // measured between servo ticks, s
  double max_period = 0.0;
  std::string calibration;  // "ok", "updated (auto)", "updated (inkwell)", "manual"
  std::uint64_t calibration_updates = 0;
  double calibration_wait = 0.0;  // s the user took to calibrate by hand
  std::string hd_model;           // HD_DEVICE_MODEL_TYPE
  double hd_max_force = 0.0;      // HD_NOMINAL_MAX_FORCE, N
  double hd_max_continuous_force = 0.0;
  double hd_max_stiffness = 0.0;  // HD_NOMINAL_MAX_STIFFNESS, N/m
  std::string library;            // the HD library loaded
};

// A PHANTOM / Touch through the OpenHaptics HD API, loaded at run time.
//
// Start initializes the device, starts the vendor's scheduler and calibrates inside it (the SDK
// answers calibration queries only from scheduler callbacks), then reads the spec and the servo
// rate: spec() is the device's only after Start. The servo thread owns the clock
// (ClockOwner::kDevice): RunServoLoop schedules an asynchronous callback that, every servo tick,
// opens an HD frame, reads the state, calls the framework's tick (which calls Read and Write),
// sends the force and closes the frame. Units: HD gives millimetres; the device reports metres,
// in the scene frame through `PhantomSettings::frame`.
class PhantomDevice final : public Device {
 public:
  ~PhantomDevice() override;
  void Configure(const PhantomSettings& settings);
  using Device::Configure;

  DeviceSpec DoSpec() const override { return spec_; }
  ClockOwner DoClockOwner() const override { return ClockOwner::kDevice; }
  void DoRunServoLoop(double duration, const std::function<bool(double)>& tick) override;
  DeviceReport DoReport() const override;
  PhantomDiagnostics diagnostics() const;

 protected:
  void DoConfigure(const ConfigNode& node) override;
  void DoStart(double period) override;
  void DoStop() noexcept override;
  void DoRead(double time, DeviceState* out) noexcept override;
  void DoWrite(const Wrench& wrench) noexcept override;

 private:
  static HDCallbackCode ServoCallback(void* self);
  HDCallbackCode Servo() noexcept;
  void CheckError(const char* what);
  HDenum CalibrationStatus();
  void Calibrate();
  DeviceSpec ResolveSpec(double period);
  // The force factor after the faults seen so far and the motors' temperature; counts the tick.
  double FaultGain(double dt, const double* temperature) noexcept;
  // Records a fault at `time`; true when it is the max_faults-th within fault_window.
  bool CountFault(double time) noexcept;

  PhantomSettings settings_;
  DeviceSpec spec_;
  hd::Library hd_;
  HHD handle_ = HD_INVALID_HANDLE;
  bool scheduler_running_ = false;

  // Servo-thread state: written by the callback, read by Read/Write inside the same tick.
  DeviceState state_;
  Eigen::Vector3d origin_{0.0, 0.0, 0.0};  // device coordinates, m
  std::uint32_t last_buttons_ = 0;
  Eigen::Vector3d pending_force_{0.0, 0.0, 0.0};  // scene frame
  const std::function<bool(double)>* tick_ = nullptr;
  double duration_ = 0.0;
  double start_time_ = -1.0;
  double last_time_ = 0.0;
  double gain_ = 1.0;   // ramp after a fault: 0 .. 1
  bool warm_ = false;   // HD_WARM_MOTORS seen, motors not yet cool
  std::array<double, 16> fault_times_{};  // ring of the latest fault times (max_faults <= 16)
  int fault_count_ = 0;
  PhantomDiagnostics diagnostics_;
  HDErrorInfo fatal_{HD_SUCCESS, 0, 0};
  std::atomic<bool> done_{false};
  std::atomic<std::uint64_t> ticks_{0};
};

}  // namespace fitfeel::phantom
