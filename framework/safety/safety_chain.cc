#include "framework/safety/safety_chain.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"

namespace fitfeel {
namespace {

// A device without a motor (the simulated robot and hand) reports +inf force and stiffness limits
// and may have no physical damping: the chain then limits nothing. Everything else is checked as
// for hardware.
void ValidateChainSpec(const DeviceSpec& spec) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (spec.max_force != kInf) {
    ValidateDeviceSpec(spec);
    return;
  }
  DeviceSpec finite = spec;
  finite.max_force = std::numeric_limits<double>::max();
  if (finite.max_continuous_force == kInf) finite.max_continuous_force = finite.max_force;
  if (finite.max_stiffness == kInf) finite.max_stiffness = finite.max_force;
  if (finite.damping == 0.0) finite.damping = 1.0;  // zero damping is allowed: no credit
  ValidateDeviceSpec(finite);
}

bool StateFinite(const PartState& s) {
  return s.position.allFinite() && s.velocity.allFinite() && s.orientation.coeffs().allFinite();
}

}  // namespace

std::string FormatSafetyReport(const SafetyReport& r) {
  std::ostringstream out;
  out.precision(6);
  out << "device: " << r.device_model << "\n";
  const ForceMapping& m = r.mapping;
  if (m.kind() == ForceMappingKind::kPerceptual) {
    out << "force mapping: perceptual, knee " << m.knee() << " N, exponent " << m.exponent()
        << ", scene top " << m.scene_top() << " N -> device top " << m.device_top() << " N\n";
  } else {
    out << "force scale: " << r.force_scale << " device N per physical N\n";
  }
  if (r.coupling == CouplingMode::kSpringDamper) {
    out << "coupling: spring-damper, K_c " << r.coupling_gains.stiffness << " N/m, B_c "
        << r.coupling_gains.damping << " N*s/m\n";
  } else {
    out << "coupling: direct rendering\n";
  }
  out << "force limits: peak " << r.peak_force_limit << " N, continuous "
      << r.continuous_force_limit << " N\n";
  out << "ticks: " << r.ticks << " (peak-limited " << r.peak_limited_ticks
      << ", continuous-limited " << r.continuous_limited_ticks << ", non-finite faults "
      << r.non_finite_faults << ", passivity controller " << r.passivity_controller_ticks << ")\n";
  out << "largest force: physical " << r.max_physical_force << " N, requested "
      << r.max_requested_force << " N, delivered " << r.max_delivered_force << " N\n";
  out << "energy: absorbed " << r.energy << " J, created (largest deficit) " << r.energy_created
      << " J, dissipated by the passivity controller " << r.controller_energy << " J\n";
  return out.str();
}

void SafetyChain::Configure(const SafetySettings& settings, const DeviceSpec& spec, double period) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw UserError("safety chain: tick period must be a positive number of seconds");
  }
  ValidateChainSpec(spec);
  const std::string who = "safety (device '" + spec.model + "'): ";
  if (!(settings.force_scale > 0.0) || !std::isfinite(settings.force_scale)) {
    throw UserError(who + "force_scale must be positive");
  }
  if (!(settings.continuous_window > 0.0)) {
    throw UserError(who + "continuous_window must be positive");
  }
  SafetyReport report;
  report.device_model = spec.model;
  report.force_scale = settings.force_scale;
  if (settings.physical_full_scale) {
    if (!(*settings.physical_full_scale > 0.0)) {
      throw UserError(who + "physical_full_scale must be positive");
    }
    report.force_scale = spec.max_continuous_force / *settings.physical_full_scale;
    if (!std::isfinite(report.force_scale)) {
      throw UserError(who +
                      "physical_full_scale needs a device with a finite continuous force "
                      "rating; give force_scale instead");
    }
  }
  report.mapping = MakeForceMapping(settings, spec, report.force_scale);
  report.coupling = settings.coupling;
  if (settings.coupling == CouplingMode::kSpringDamper) {
    if (!(spec.damping > 0.0)) {
      throw UserError(who +
                      "the device has no physical damping, so no virtual coupling obeys "
                      "the passivity bound b > K_c*T/2 + B_c; use coupling: direct");
    }
    CouplingGains gains = DefaultCouplingGains(spec, period);
    if (settings.coupling_stiffness) gains.stiffness = *settings.coupling_stiffness;
    if (settings.coupling_damping) gains.damping = *settings.coupling_damping;
    if (!CouplingGainsArePassive(gains, spec, period)) {
      std::ostringstream msg;
      msg << who << "coupling gains K_c = " << gains.stiffness << " N/m, B_c = " << gains.damping
          << " N*s/m break the passivity bound at T = " << period
          << " s: need K_c <= " << spec.max_stiffness << " N/m and b = " << spec.damping
          << " N*s/m > K_c*T/2 + B_c = " << gains.stiffness * period / 2.0 + gains.damping;
      throw UserError(msg.str());
    }
    if (!(settings.proxy_mass >= 0.0) || !std::isfinite(settings.proxy_mass)) {
      throw UserError(who + "proxy_mass must be zero or positive");
    }
    coupling_.Configure(gains, settings.proxy_mass);
    report.coupling_gains = gains;
  }
  observer_.Configure(spec.damping, settings.credit_device_damping && spec.credit_damping,
                      settings.passivity_controller,
                      settings.passivity_max_damping.value_or(spec.damping));
  limiter_.Configure(spec.max_force, spec.max_continuous_force, settings.continuous_window);
  report.peak_force_limit = spec.max_force;
  report.continuous_force_limit = spec.max_continuous_force;

  settings_ = settings;
  spec_ = spec;
  period_ = period;
  report_ = report;
  configured_ = true;
  started_ = false;
  physical_stiffness_ = 0.0;
  stiffness_scale_ = report_.mapping.Slope(0.0);
}

void SafetyChain::Reset(const PartState& device) noexcept {
  // Only the per-run numbers: the configured part (and its string) stays, so nothing allocates.
  SafetyReport& r = report_;
  r.ticks = r.peak_limited_ticks = r.continuous_limited_ticks = 0;
  r.non_finite_faults = r.passivity_controller_ticks = 0;
  r.max_physical_force = r.max_requested_force = r.max_delivered_force = 0.0;
  r.energy = r.energy_created = r.controller_energy = 0.0;
  const Eigen::Vector3d p = device.position.allFinite() ? device.position : Eigen::Vector3d::Zero();
  const Eigen::Vector3d v = device.velocity.allFinite() ? device.velocity : Eigen::Vector3d::Zero();
  coupling_.Reset(p, v);
  observer_.Reset(p);
  limiter_.Reset();
  started_ = true;
}

void SafetyChain::SimulatedState(const PartState& device, PartState* out) const noexcept {
  *out = device;
  if (settings_.coupling == CouplingMode::kSpringDamper && started_) {
    out->position = coupling_.proxy_position();
    out->velocity = coupling_.proxy_velocity();
  }
}

void SafetyChain::SetEnvironmentStiffness(double physical_stiffness) noexcept {
  physical_stiffness_ =
      (std::isfinite(physical_stiffness) && physical_stiffness > 0.0) ? physical_stiffness : 0.0;
}

Wrench SafetyChain::Apply(const Wrench& physical, const PartState& device, double dt) noexcept {
  Wrench out;
  if (!configured_) return out;  // nothing configured: never push a device
  if (!started_) Reset(device);
  ++report_.ticks;
  if (!StateFinite(device)) {
    ++report_.non_finite_faults;
    observer_.Hold(Eigen::Vector3d::Zero());
    return out;
  }
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    ++report_.non_finite_faults;
    dt = period_;
  }
  observer_.Observe(device.position, dt);
  if (!physical.AllFinite()) {
    ++report_.non_finite_faults;
    observer_.Hold(Eigen::Vector3d::Zero());
    return out;
  }
  Eigen::Vector3d physical_force = physical.force;
  Eigen::Vector3d physical_torque = physical.torque;
  if (settings_.torque_lever > 0.0) {
    // The torque about the axis as the handle's tangential force (SafetySettings::torque_lever).
    physical_force.x() += physical_torque.y() / settings_.torque_lever;
    physical_torque.y() = 0.0;
  }
  report_.max_physical_force = std::max(report_.max_physical_force, physical_force.norm());
  // The mapping acts on the force's magnitude; the direction, and the torque's share, are kept.
  const double magnitude = physical_force.norm();
  const double scale = report_.mapping.Ratio(magnitude);
  stiffness_scale_ = report_.mapping.Slope(magnitude);
  Eigen::Vector3d force = scale * physical_force;
  if (settings_.coupling == CouplingMode::kSpringDamper) {
    force = coupling_.Step(force, device.position, device.velocity,
                           physical_stiffness_ * stiffness_scale_, dt);
    if (!coupling_.proxy_position().allFinite() || !coupling_.proxy_velocity().allFinite()) {
      coupling_.Reset(device.position, device.velocity);
      force.setZero();
      ++report_.non_finite_faults;
    }
  }
  force = observer_.Control(force, dt);
  report_.max_requested_force = std::max(report_.max_requested_force, force.norm());
  ForceLimiter::Flags flags;
  force = limiter_.Apply(force, dt, &flags);
  if (flags.peak) ++report_.peak_limited_ticks;
  if (flags.continuous) ++report_.continuous_limited_ticks;
  out.force = force;
  // The listed devices render no torque and their specs carry no torque limit: torque is scaled
  // as the force is and passed on (a 3-DOF device ignores it).
  out.torque = scale * physical_torque;
  if (!out.AllFinite()) {
    ++report_.non_finite_faults;
    out.SetZero();
  }
  observer_.Hold(out.force);
  report_.max_delivered_force = std::max(report_.max_delivered_force, out.force.norm());
  report_.energy = observer_.energy();
  report_.energy_created = observer_.energy_created();
  report_.controller_energy = observer_.controller_energy();
  report_.passivity_controller_ticks = static_cast<std::uint64_t>(observer_.controller_ticks());
  return out;
}

}  // namespace fitfeel
