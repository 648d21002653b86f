#include "framework/stability/stiction_experiment.h"

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"
#include "framework/safety/safety_chain.h"

namespace fitfeel {
namespace {

void CheckStiction(bool ok, const char* what) {
  if (!ok) throw UserError(std::string("stiction experiment: ") + what);
}

}  // namespace

StictionOutcome RunStictionExperiment(const StictionExperiment& e) {
  ValidateDeviceSpec(e.spec);
  const StickSlipFriction friction(e.friction);  // checks the coefficients
  CheckStiction(std::isfinite(e.rate) && e.rate > 0.0, "rate must be positive");
  CheckStiction(std::isfinite(e.force_scale) && e.force_scale > 0.0,
                "force scale must be positive");
  CheckStiction(std::isfinite(e.normal_force) && e.normal_force > 0.0,
                "normal force must be positive");
  CheckStiction(std::isfinite(e.hand_mass) && e.hand_mass > 0.0, "hand mass must be positive");
  CheckStiction(std::isfinite(e.push_force) && e.push_force > 0.0 &&
                    e.push_force < e.spec.max_continuous_force,
                "push force must be positive and below the device's continuous force rating");
  CheckStiction(std::isfinite(e.horizon) && e.horizon > 0.0, "horizon must be positive");
  CheckStiction(e.substeps >= 1 && e.substeps <= 10000, "substeps must be in 1..10000");
  const double period = 1.0 / e.rate;
  const auto ticks = static_cast<std::uint64_t>(std::ceil(e.horizon * e.rate));
  CheckStiction(ticks <= 100'000'000, "horizon x rate is more than 1e8 ticks");

  SafetySettings settings;
  settings.force_scale = e.force_scale;
  settings.coupling =
      e.method == RenderingMethod::kDirect ? CouplingMode::kDirect : CouplingMode::kSpringDamper;
  SafetyChain chain;
  chain.Configure(settings, e.spec, period);

  // The junctions' spring as the device renders it, and in series with the coupling.
  const double k_contact = friction.StickingStiffness(e.normal_force) * e.force_scale;
  double k_static = k_contact;
  if (e.method == RenderingMethod::kCoupled) {
    const double kc = chain.report().coupling_gains.stiffness;
    k_static = kc * k_contact / (kc + k_contact);
  }
  const double y_rest = e.push_force / k_static;
  const double m = e.hand_mass, b = e.spec.damping;
  auto energy = [&](double y, double v) {
    return 0.5 * m * v * v + 0.5 * k_static * (y - y_rest) * (y - y_rest);
  };

  StictionOutcome out;
  out.stored_bound = 0.5 * e.friction.static_coefficient * e.normal_force *
                     e.friction.breakaway_displacement * e.force_scale;
  double y = 0.0, v = 0.0;
  out.initial_energy = energy(y, v);
  const double h = period / e.substeps;
  const double decay = std::exp(-b * h / m);
  const double final_window_start = 0.9 * e.horizon;
  FrictionState state;
  PartState device, law_state;
  Wrench physical;
  for (std::uint64_t k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) * period;
    device.time = t;
    device.position = Eigen::Vector3d(0.0, y, 0.0);
    device.velocity = Eigen::Vector3d(0.0, v, 0.0);
    if (k == 0) chain.Reset(device);
    chain.SimulatedState(device, &law_state);
    physical.SetZero();
    physical.force.y() =
        friction.Step({law_state.position.y(), 0.0}, e.normal_force, &state).x();
    if (e.method == RenderingMethod::kCoupled && e.stiffness_hint) {
      chain.SetEnvironmentStiffness(friction.StickingStiffness(e.normal_force));
    }
    double f = chain.Apply(physical, device, period).force.y();
    if (!std::isfinite(f)) {
      ++out.non_finite;
      f = 0.0;
    }
    out.peak_force = std::max(out.peak_force, std::abs(f));
    for (int s = 1; s <= e.substeps; ++s) {
      // m v' = f + push - b v with f held: exact.
      const double total = f + e.push_force;
      const double y0 = y;
      if (b > 0.0) {
        const double v_inf = total / b, dv = v - v_inf;
        y += v_inf * h + dv * (m / b) * (1.0 - decay);
        v = v_inf + dv * decay;
      } else {
        y += v * h + 0.5 * total / m * h * h;
        v += total / m * h;
      }
      out.contact_work += f * (y - y0);
      if (t + period * s / e.substeps >= final_window_start) {
        out.final_energy = std::max(out.final_energy, energy(y, v));
      }
    }
  }
  out.displacement = y;
  out.final_speed = std::abs(v);
  out.sliding = state.sliding;
  out.stable = out.non_finite == 0 && std::isfinite(out.final_energy) &&
               out.final_energy < out.initial_energy;
  return out;
}

}  // namespace fitfeel
