#include "framework/stability/stiction_experiment.h"

#include <cmath>

namespace fitfeel {

StictionOutcome RunStictionExperiment(const StictionExperiment& e) {
  const StickSlipFriction friction(e.friction);  // checks the coefficients
  SampledHand hand(e, "stiction experiment");
  hand.Require(std::isfinite(e.normal_force) && e.normal_force > 0.0,
               "normal force must be positive");

  // The junctions' spring as the device renders it, and in series with the coupling.
  const double k_static =
      hand.StaticStiffness(friction.StickingStiffness(e.normal_force) * e.force_scale);
  const double y_rest = e.push_force / k_static;
  const double m = e.hand_mass;
  auto energy = [&](double y, double v) {
    return 0.5 * m * v * v + 0.5 * k_static * (y - y_rest) * (y - y_rest);
  };

  StictionOutcome out;
  out.stored_bound = 0.5 * e.friction.static_coefficient * e.normal_force *
                     e.friction.breakaway_displacement * e.force_scale;
  out.initial_energy = energy(0.0, 0.0);
  FrictionState state;
  const auto junctions = [&](std::uint64_t, const PartState&, const PartState& law) {
    const double f = friction.Step({law.position.y(), 0.0}, e.normal_force, &state).x();
    if (e.method == RenderingMethod::kCoupled && e.stiffness_hint) {
      hand.chain().SetEnvironmentStiffness(friction.StickingStiffness(e.normal_force));
    }
    return f;
  };
  const auto work = [&](double f, double y0, double y) { out.contact_work += f * (y - y0); };
  const SampledHand::Result run = hand.Run(0.0, 0.0, junctions, work, energy);
  out.final_energy = run.final_energy;
  out.peak_force = run.peak_force;
  out.non_finite = run.non_finite;
  out.displacement = run.y;
  out.final_speed = std::abs(run.v);
  out.sliding = state.sliding;
  out.stable = out.non_finite == 0 && std::isfinite(out.final_energy) &&
               out.final_energy < out.initial_energy;
  return out;
}

}  // namespace fitfeel
