#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "framework/core/config_node.h"
#include "framework/core/export.h"
#include "framework/core/wrench.h"
#include "framework/device/device_report.h"

namespace fitfeel {

// How the safety chain turns a scene's force into the device's (framework/safety/force_mapping.h).
enum class ForceMappingKind {
  kLinear,      // one factor for every force (SafetySettings::force_scale)
  kPerceptual,  // identity up to a knee, then a power law that compresses the scene's decades
};

// Limits and native properties of a haptic device (data, overridable by the scenario).
struct DeviceSpec {
  std::string model;
  double max_force = 0.0;             // N, peak
  double max_continuous_force = 0.0;  // N
  double max_stiffness = 0.0;         // N/m, largest stable rendered stiffness
  double damping = 0.0;               // N*s/m, physical damping usable for passivity
  // Whether the passivity observer may count `damping` as dissipation: false for hardware whose
  // damping is a bound inferred from its stiffness limit rather than a measurement.
  bool credit_damping = true;
  Eigen::Vector3d workspace{0.0, 0.0, 0.0};  // extent of the reachable box, m
  double native_rate = 1000.0;               // Hz
  // The force mapping this device renders with unless the scenario's `safety` section names one.
  ForceMappingKind force_mapping = ForceMappingKind::kLinear;
};

// One sample of the device (or hand) state, in the scene frame: y is the mating axis.
struct DeviceState {
  double time = 0.0;  // s since the start of the run
  Eigen::Vector3d position{0.0, 0.0, 0.0};
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity{0.0, 0.0, 0.0};
  Eigen::Vector3d angular_velocity{0.0, 0.0, 0.0};
  std::uint32_t buttons = 0;
  // Wrench the device delivered in the previous tick after its own limits (for recording).
  Wrench delivered;
};

// A contact stiffness handed over per tick (N/m) as its users take it: what is not a finite,
// non-negative stiffness is none (0).
inline double SanitizedStiffness(double stiffness) noexcept {
  return stiffness >= 0.0 && stiffness < 1e300 ? stiffness : 0.0;
}

// Who calls the tick: the framework's scheduler, or the device vendor's servo thread.
enum class ClockOwner { kFramework, kDevice };

// A device plugin. Configure and Start may allocate and throw; Read and Write run in the tick.
// Every public method is non-virtual and calls a protected virtual Do... that a plugin overrides.
class FITFEEL_API Device {
 public:
  virtual ~Device();

  // Parses the scenario's `device` node (after the plugin key); throws ScenarioError.
  void Configure(const ConfigNode& node);
  // Opens the hardware or prepares the simulation for a run of `period` seconds per tick.
  void Start(double period);
  void Stop() noexcept;

  // Per tick. `time` is the tick's scheduled time (virtual or real) in seconds since start.
  void Read(double time, DeviceState* out) noexcept;
  // Per tick: the wrench to apply (already scaled and bounded by the safety chain).
  void Write(const Wrench& wrench) noexcept;
  // Per tick, before Write: the stiffness (N/m) of the rendered wrench at the handle, 0 when free:
  // the local model that goes with the force, as an intermediate representation hands a device a
  // plane and its stiffness. A device that simulates its own inertia (the scripted hand)
  // integrates the contact implicitly with it (a press fit is far stiffer than an explicit step at
  // 1 kHz can hold); hardware ignores it.
  void SetEnvironmentStiffness(double stiffness) noexcept {
    DoSetEnvironmentStiffness(SanitizedStiffness(stiffness));
  }
  // The device's limits. A device that measures them (hardware) knows them only after Start.
  DeviceSpec spec() const { return DoSpec(); }
  // The tilt the device holds the moving part at for the whole run, known once configured: the
  // (x, z) components of the rotation vector that turns the scene's +y onto the part's axis, rad
  // (MatingPose::tilt). A contact analyzer that tabulates its contact prepares it for this tilt
  // (ModelSettings::held_tilt). Empty for a device whose tilt is sensed or varies (hardware).
  std::optional<Eigen::Vector2d> held_tilt() const { return DoHeldTilt(); }
  // How stiffly the holder keeps that tilt about the point it holds the part at, N*m/rad:
  // infinite (the default) for a rigid holder (a robot); finite for a hand's fingers and wrist,
  // which let the contact turn the part towards the mating axis (ModelSettings).
  double held_tilt_stiffness() const { return DoHeldTiltStiffness(); }
  // The largest y the part's leading end reaches within a run of `duration` s, m, for a device
  // whose trajectory is fixed in advance (a robot); +inf when the device cannot bound it (a hand
  // follows its contact, hardware its user). A prepare need not tabulate a contact further in.
  double reach(double duration) const { return DoReach(duration); }
  // The largest turn |angle| about the mating axis the part reaches within a run of `duration` s,
  // rad, for a device whose trajectory is fixed in advance (a rotary drive's swing); +inf when
  // the device cannot bound it. A prepare need not tabulate a contact past it.
  double angular_reach(double duration) const { return DoAngularReach(duration); }
  ClockOwner clock_owner() const { return DoClockOwner(); }
  // For devices that own the clock: run `tick(time)` from the vendor's servo thread at the native
  // rate until it returns false or `duration` seconds pass. Throws UserError for a duration that
  // is not a positive finite time, an empty tick, or a device that cannot.
  void RunServoLoop(double duration, const std::function<bool(double)>& tick);
  // True while the device wants the run to continue (e.g. a replay that has not ended).
  bool active() const { return DoActive(); }
  // After a run: what the device saw (faults, recoveries, calibration, measured rate), written to
  // summary.json's `device_report`; empty when it has nothing to report.
  DeviceReport report() const { return DoReport(); }

 protected:
  virtual DeviceSpec DoSpec() const = 0;
  virtual std::optional<Eigen::Vector2d> DoHeldTilt() const { return std::nullopt; }
  virtual double DoHeldTiltStiffness() const { return std::numeric_limits<double>::infinity(); }
  virtual double DoReach(double) const { return std::numeric_limits<double>::infinity(); }
  virtual double DoAngularReach(double) const { return std::numeric_limits<double>::infinity(); }
  virtual ClockOwner DoClockOwner() const { return ClockOwner::kFramework; }
  // Default: the device does not own a clock (throws UnsupportedError).
  virtual void DoRunServoLoop(double duration, const std::function<bool(double)>& tick);
  virtual bool DoActive() const { return true; }
  virtual DeviceReport DoReport() const { return {}; }
  virtual void DoConfigure(const ConfigNode& node) = 0;
  virtual void DoStart(double period) = 0;
  virtual void DoStop() noexcept {}
  virtual void DoRead(double time, DeviceState* out) noexcept = 0;
  virtual void DoWrite(const Wrench& wrench) noexcept = 0;
  virtual void DoSetEnvironmentStiffness(double) noexcept {}
};

}  // namespace fitfeel
