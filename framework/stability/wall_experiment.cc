#include "framework/stability/wall_experiment.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"
#include "framework/safety/safety_chain.h"

namespace fitfeel {
namespace {

// The final energy is the largest E over the last tenth of the horizon. E does not oscillate at
// twice the frequency the way the kinetic energy alone does, and the window's maximum does not
// depend on where in a cycle the run ends.
constexpr double kFinalWindowShare = 0.1;

void CheckWall(bool ok, const std::string& what) {
  if (!ok) throw UserError("stability experiment: " + what);
}

// The hand between two samples: m v' = f - b v with f constant, solved exactly.
struct HandStep {
  double decay = 1.0;  // exp(-b h / m)
  double h = 0.0;
  double b = 0.0;
  double m = 0.0;
  void Advance(double force, double* y, double* v) const {
    if (b > 0.0) {
      const double v_inf = force / b;
      const double dv = *v - v_inf;
      *y += v_inf * h + dv * (m / b) * (1.0 - decay);
      *v = v_inf + dv * decay;
    } else {
      *y += *v * h + 0.5 * force / m * h * h;
      *v += force / m * h;
    }
  }
};

}  // namespace

std::string ToString(RenderingMethod method) {
  return method == RenderingMethod::kDirect ? "direct" : "coupled";
}

double PassivityMargin(double physical_damping, double stiffness, double damping, double period) {
  return physical_damping - (stiffness * period / 2.0 + std::abs(damping));
}

WallOutcome RunWallExperiment(const WallExperiment& e) {
  ValidateDeviceSpec(e.spec);
  CheckWall(std::isfinite(e.rate) && e.rate > 0.0, "rate must be positive");
  CheckWall(std::isfinite(e.stiffness) && e.stiffness > 0.0, "stiffness must be positive");
  CheckWall(std::isfinite(e.damping), "damping must be finite");
  CheckWall(std::isfinite(e.force_scale) && e.force_scale > 0.0, "force scale must be positive");
  CheckWall(std::isfinite(e.hand_mass) && e.hand_mass > 0.0, "hand mass must be positive");
  // The experiment is about a resting contact: something must hold the hand on the wall, and the
  // device must be able to hold it back for good (its continuous rating).
  CheckWall(std::isfinite(e.push_force) && e.push_force > 0.0 &&
                e.push_force < e.spec.max_continuous_force,
            "push force must be positive and below the device's continuous force rating");
  CheckWall(std::isfinite(e.approach_speed) && e.approach_speed >= 0.0,
            "approach speed must be zero or positive");
  CheckWall(std::isfinite(e.horizon) && e.horizon > 0.0, "horizon must be positive");
  CheckWall(e.substeps >= 1 && e.substeps <= 10000, "substeps must be in 1..10000");
  const double period = 1.0 / e.rate;
  const auto ticks = static_cast<std::uint64_t>(std::ceil(e.horizon * e.rate));
  CheckWall(ticks <= 100'000'000, "horizon x rate is more than 1e8 ticks");

  SafetySettings settings;
  settings.force_scale = e.force_scale;
  settings.coupling =
      e.method == RenderingMethod::kDirect ? CouplingMode::kDirect : CouplingMode::kSpringDamper;
  SafetyChain chain;
  chain.Configure(settings, e.spec, period);

  // Physical law: the wall the scene renders, in physical units.
  const double k_physical = e.stiffness / e.force_scale;
  const double b_physical = e.damping / e.force_scale;

  // Where the hand rests and how stiff the rendering is there, for the oscillation energy.
  double k_static = e.stiffness;
  double y_rest = e.push_force / e.stiffness;
  if (e.method == RenderingMethod::kCoupled) {
    const double kc = chain.report().coupling_gains.stiffness;
    k_static = kc * e.stiffness / (kc + e.stiffness);
    y_rest = e.push_force / e.stiffness + e.push_force / kc;
  }
  const double m = e.hand_mass;
  // The continuous (unsampled) system's energy above its resting state: kinetic, the wall's
  // one-sided spring as the device can render it (its force capped at the peak rating) and the
  // push's potential. Without sampling it can only decrease (dE/dt = -b v^2), so any growth is
  // energy the sampled rendering created; it stays meaningful when an unstable hand bounces off
  // the wall or drives it into saturation.
  const double y_saturated = e.spec.max_force / k_static;
  auto potential = [&](double y) {
    const double inside = std::clamp(y, 0.0, y_saturated);
    return 0.5 * k_static * inside * inside + e.spec.max_force * std::max(0.0, y - y_saturated) -
           e.push_force * y;
  };
  const double rest_potential = potential(y_rest);
  auto energy = [&](double y, double v) { return 0.5 * m * v * v + potential(y) - rest_potential; };

  WallOutcome out;
  out.bound_margin = PassivityMargin(e.spec.damping, e.stiffness, e.damping, period);
  out.bound_ok = out.bound_margin > 0.0;

  HandStep step;
  step.h = period / e.substeps;
  step.b = e.spec.damping;
  step.m = m;
  step.decay = std::exp(-step.b * step.h / m);

  // The experiment is about the stability of a resting contact, so the hand must not bounce off
  // the wall on arrival (a bounce loses energy in flight and hides the wall's own behaviour): it
  // arrives at the approach speed or at half the speed whose impact would lift it off the linear
  // wall again (amplitude v sqrt(m / K_s) equal to the static deflection push / K_s), whichever is
  // slower.
  const double bounce_speed = e.push_force / std::sqrt(k_static * m);
  double y = 0.0;
  double v = std::min(e.approach_speed, 0.5 * bounce_speed);
  out.initial_energy = energy(y, v);
  const double final_window_start = e.horizon * (1.0 - kFinalWindowShare);
  double last_law_position = 0.0;
  PartState device;
  PartState law_state;
  Wrench physical;
  for (std::uint64_t k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) * period;
    device.time = t;
    device.position = Eigen::Vector3d(0.0, y, 0.0);
    device.velocity = Eigen::Vector3d(0.0, v, 0.0);
    if (k == 0) chain.Reset(device);
    chain.SimulatedState(device, &law_state);
    const double p = law_state.position.y();
    // Backward difference of the sampled position, as a device driver estimates velocity from
    // encoder counts: the velocity Colgate & Schenkel's bound assumes.
    const double v_est = k == 0 ? v : (p - last_law_position) / period;
    last_law_position = p;
    physical.SetZero();
    if (p > 0.0) physical.force.y() = -k_physical * p - b_physical * v_est;
    if (e.stiffness_hint) chain.SetEnvironmentStiffness(p > 0.0 ? k_physical : 0.0);
    const Wrench command = chain.Apply(physical, device, period);
    double f = command.force.y();
    if (!std::isfinite(f)) {
      ++out.non_finite;
      f = 0.0;
    }
    out.peak_force = std::max(out.peak_force, std::abs(f));
    for (int s = 1; s <= e.substeps; ++s) {
      step.Advance(f + e.push_force, &y, &v);
      out.peak_penetration = std::max(out.peak_penetration, y);
      const double ts = t + period * s / e.substeps;
      if (ts >= final_window_start) out.final_energy = std::max(out.final_energy, energy(y, v));
    }
    ++out.ticks;
  }
  out.peak_requested_force = chain.report().max_requested_force;
  out.energy_growth = out.final_energy - out.initial_energy;
  out.stable = std::isfinite(out.final_energy) && out.final_energy < out.initial_energy &&
               out.non_finite == 0;
  return out;
}

double MeasureStabilityBoundary(WallExperiment e, double low, double high, double tolerance) {
  CheckWall(low > 0.0 && high > low && tolerance > 0.0,
            "boundary search needs 0 < low < high and a positive tolerance");
  e.stiffness = low;
  const bool low_stable = RunWallExperiment(e).stable;
  e.stiffness = high;
  const bool high_stable = RunWallExperiment(e).stable;
  if (!low_stable || high_stable) {
    std::ostringstream msg;
    msg << "stability boundary: K = " << low << " N/m is " << (low_stable ? "" : "un")
        << "stable and K = " << high << " N/m is " << (high_stable ? "" : "un")
        << "stable; need stable below and unstable above";
    throw UserError(msg.str());
  }
  while (high / low > 1.0 + tolerance) {
    const double mid = std::sqrt(low * high);
    e.stiffness = mid;
    (RunWallExperiment(e).stable ? low : high) = mid;
  }
  return std::sqrt(low * high);
}

}  // namespace fitfeel
