#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "devices/phantom/phantom_hd_library.h"
#include "framework/device/device.h"

namespace fitfeel::phantom {

struct PhantomSettings {
  // Spec: `spec` if given, else the table entry for `model`, else the table entry for the model
  // the driver reports, else the driver's nominal values. Peak and continuous force are then
  // lowered to the driver's nominal values where those are smaller.
  std::string model;
  std::optional<DeviceSpec> spec;
  // Run the driver's automatic calibration when it asks for an update.
  bool auto_calibrate = true;
};

// What the servo loop saw, for the run summary and the tests.
struct PhantomDiagnostics {
  std::uint64_t ticks = 0;
  std::uint64_t force_errors = 0;    // force errors popped from the HD error stack
  std::uint64_t zeroed_ticks = 0;    // ticks sent zero force while recovering from one
  std::uint64_t clamped_writes = 0;  // writes above the driver's nominal max force
  std::uint32_t last_error = 0;      // HD_ code of the last error seen (0: none)
  double max_force_sent = 0.0;       // N
  std::string hd_model;              // HD_DEVICE_MODEL_TYPE
  double hd_max_force = 0.0;         // HD_NOMINAL_MAX_FORCE, N
  double hd_max_continuous_force = 0.0;
  std::string library;  // the HD library loaded
};

// A PHANTOM / Touch through the OpenHaptics HD API, loaded at run time.
//
// The vendor's servo thread owns the clock (ClockOwner::kDevice): RunServoLoop schedules an
// asynchronous callback that, every servo tick, opens an HD frame, reads the state, calls the
// framework's tick (which calls Read and Write), sends the force and closes the frame. Units: HD
// gives millimetres; the device reports metres. Frame: the device's (x right, y up, z towards the
// user), so the scene's mating axis y is the device's vertical.
class PhantomDevice final : public Device {
 public:
  ~PhantomDevice() override;
  void Configure(const PhantomSettings& settings);
  using Device::Configure;

  DeviceSpec spec() const override { return spec_; }
  ClockOwner clock_owner() const override { return ClockOwner::kDevice; }
  void RunServoLoop(double duration, const std::function<bool(double)>& tick) override;
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
  void Calibrate();
  DeviceSpec ResolveSpec();

  PhantomSettings settings_;
  DeviceSpec spec_;
  hd::Library hd_;
  HHD handle_ = HD_INVALID_HANDLE;

  // Servo-thread state: written by the callback, read by Read/Write inside the same tick.
  DeviceState state_;
  Eigen::Vector3d pending_force_{0.0, 0.0, 0.0};
  const std::function<bool(double)>* tick_ = nullptr;
  double duration_ = 0.0;
  double start_time_ = -1.0;
  int recover_ticks_ = 0;
  PhantomDiagnostics diagnostics_;
  HDErrorInfo fatal_{HD_SUCCESS, 0, 0};
  std::atomic<bool> done_{false};
  std::atomic<std::uint64_t> ticks_{0};
};

}  // namespace fitfeel::phantom
