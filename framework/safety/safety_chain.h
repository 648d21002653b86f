#pragma once

#include <cstdint>
#include <string>

#include "framework/core/export.h"
#include "framework/core/wrench.h"
#include "framework/device/device.h"
#include "framework/runtime/part_state.h"
#include "framework/safety/force_limiter.h"
#include "framework/safety/force_mapping.h"
#include "framework/safety/passivity_observer.h"
#include "framework/safety/safety_settings.h"
#include "framework/safety/virtual_coupling.h"

namespace fitfeel {

// What the safety chain did during a run, for the run summary. Forces in device newtons unless
// named physical.
struct SafetyReport {
  std::string device_model;
  double force_scale = 1.0;  // device N per physical N (the linear mapping's)
  ForceMapping mapping;      // scene force -> device force (default: linear, 1)
  CouplingMode coupling = CouplingMode::kSpringDamper;
  CouplingGains coupling_gains;  // zero for direct rendering
  double peak_force_limit = 0.0;
  double continuous_force_limit = 0.0;

  std::uint64_t ticks = 0;
  std::uint64_t peak_limited_ticks = 0;
  std::uint64_t continuous_limited_ticks = 0;
  std::uint64_t non_finite_faults = 0;  // ticks whose input or output was NaN/inf: zero sent
  std::uint64_t passivity_controller_ticks = 0;

  double max_physical_force = 0.0;   // N, largest finite law force seen
  double max_requested_force = 0.0;  // before the limits
  double max_delivered_force = 0.0;  // after the limits: never above peak_force_limit

  double energy = 0.0;             // J the rendering absorbed from the hand (observer)
  double energy_created = 0.0;     // J, largest deficit the observer saw
  double controller_energy = 0.0;  // J the passivity controller dissipated
};

// The report as lines for the run summary, with units, e.g.
//   "force scale: 0.01 device N per physical N".
FITFEEL_API std::string FormatSafetyReport(const SafetyReport& report);

// Everything between the resistance law and Device::Write.
//
// Prepare time: Configure (may throw UserError). Per tick, in this order:
//   1. chain.SimulatedState(device_state, &law_state)  // where to evaluate the stage
//   2. stage.Evaluate(law_state, stage_state, &out)     // physical wrench on the simulated part
//   3. [optional] chain.SetEnvironmentStiffness(k)      // physical N/m when the law knows it
//   4. device.Write(chain.Apply(out.wrench, device_state, dt))
// With the coupling, the law must be evaluated at the proxy (step 1), not at the device.
// Every per-tick method is noexcept and allocation-free.
class FITFEEL_API SafetyChain {
 public:
  // Throws UserError when the spec is invalid or the settings' coupling gains break the bound.
  void Configure(const SafetySettings& settings, const DeviceSpec& spec, double period);

  // Starts a run at this device state: proxy at the handle, energy and counters at zero. Apply
  // calls it on its first tick if nobody did.
  void Reset(const PartState& device) noexcept;

  // Per tick: the state the law sees (the device's, with the proxy's position and velocity when
  // coupled).
  void SimulatedState(const PartState& device, PartState* out) const noexcept;
  // Per tick, optional: the environment's current stiffness, physical N/m (0 when free). Apply
  // hands the coupling this stiffness times the mapping's slope at the tick's force.
  void SetEnvironmentStiffness(double physical_stiffness) noexcept;
  // Per tick: the law's wrench on the simulated part (physical N, N*m) -> the device's wrench.
  // Never returns a non-finite wrench or a force above the device's peak rating.
  Wrench Apply(const Wrench& physical, const PartState& device, double dt) noexcept;

  const SafetyReport& report() const { return report_; }
  const SafetySettings& settings() const { return settings_; }
  const DeviceSpec& spec() const { return spec_; }
  double force_scale() const { return report_.force_scale; }
  const ForceMapping& mapping() const { return report_.mapping; }
  // Device N per physical N of a small change of the last tick's force (the mapping's slope at
  // it): what turns a physical stiffness into the device's.
  double stiffness_scale() const { return stiffness_scale_; }
  const VirtualCoupling& coupling() const { return coupling_; }
  const PassivityObserver& observer() const { return observer_; }

 private:
  SafetySettings settings_;
  DeviceSpec spec_;
  double period_ = 1e-3;
  bool configured_ = false;
  bool started_ = false;
  double physical_stiffness_ = 0.0;  // N/m, SetEnvironmentStiffness's
  double stiffness_scale_ = 1.0;     // the mapping's slope at the last tick's force
  VirtualCoupling coupling_;
  PassivityObserver observer_;
  ForceLimiter limiter_;
  SafetyReport report_;
};

}  // namespace fitfeel
