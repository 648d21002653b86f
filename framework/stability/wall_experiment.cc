#include "framework/stability/wall_experiment.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

void CheckWall(bool ok, const std::string& what) {
  if (!ok) throw UserError("stability experiment: " + what);
}

}  // namespace

double PassivityMargin(double physical_damping, double stiffness, double damping, double period) {
  return physical_damping - (stiffness * period / 2.0 + std::abs(damping));
}

WallOutcome RunWallExperiment(const WallExperiment& e) {
  SampledHand hand(e, "stability experiment");
  hand.Require(std::isfinite(e.stiffness) && e.stiffness > 0.0, "stiffness must be positive");
  hand.Require(std::isfinite(e.damping), "damping must be finite");
  hand.Require(std::isfinite(e.approach_speed) && e.approach_speed >= 0.0,
               "approach speed must be zero or positive");
  const double period = hand.period();

  // Physical law: the wall the scene renders, in physical units.
  const double k_physical = e.stiffness / e.force_scale;
  const double b_physical = e.damping / e.force_scale;

  // Where the hand rests and how stiff the rendering is there, for the oscillation energy.
  const double k_static = hand.StaticStiffness(e.stiffness);
  double y_rest = e.push_force / e.stiffness;
  if (e.method == RenderingMethod::kCoupled) {
    y_rest += e.push_force / hand.chain().report().coupling_gains.stiffness;
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

  // The experiment is about the stability of a resting contact, so the hand must not bounce off
  // the wall on arrival (a bounce loses energy in flight and hides the wall's own behaviour): it
  // arrives at the approach speed or at half the speed whose impact would lift it off the linear
  // wall again (amplitude v sqrt(m / K_s) equal to the static deflection push / K_s), whichever is
  // slower.
  const double bounce_speed = e.push_force / std::sqrt(k_static * m);
  const double v0 = std::min(e.approach_speed, 0.5 * bounce_speed);
  out.initial_energy = energy(0.0, v0);
  double last_law_position = 0.0;
  const auto wall = [&](std::uint64_t k, const PartState& device, const PartState& law) {
    const double p = law.position.y();
    // Backward difference of the sampled position, as a device driver estimates velocity from
    // encoder counts: the velocity Colgate & Schenkel's bound assumes.
    const double v_est = k == 0 ? device.velocity.y() : (p - last_law_position) / period;
    last_law_position = p;
    if (e.stiffness_hint) hand.chain().SetEnvironmentStiffness(p > 0.0 ? k_physical : 0.0);
    return p > 0.0 ? -k_physical * p - b_physical * v_est : 0.0;
  };
  const auto penetration = [&](double, double, double y) {
    out.peak_penetration = std::max(out.peak_penetration, y);
  };
  const SampledHand::Result run = hand.Run(0.0, v0, wall, penetration, energy);
  out.final_energy = run.final_energy;
  out.peak_force = run.peak_force;
  out.ticks = run.ticks;
  out.non_finite = run.non_finite;
  out.peak_requested_force = hand.chain().report().max_requested_force;
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
