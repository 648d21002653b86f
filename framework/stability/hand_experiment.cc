#include "framework/stability/hand_experiment.h"

#include <utility>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"

namespace fitfeel {

std::string ToString(RenderingMethod method) {
  return method == RenderingMethod::kDirect ? "direct" : "coupled";
}

SampledHand::SampledHand(const HandExperiment& e, std::string name)
    : name_(std::move(name)),
      push_force_(e.push_force),
      horizon_(e.horizon),
      substeps_(e.substeps) {
  ValidateDeviceSpec(e.spec);
  Require(std::isfinite(e.rate) && e.rate > 0.0, "rate must be positive");
  Require(std::isfinite(e.force_scale) && e.force_scale > 0.0, "force scale must be positive");
  Require(std::isfinite(e.hand_mass) && e.hand_mass > 0.0, "hand mass must be positive");
  // The experiments are about a resting contact: something must hold the hand against it, and
  // the device must be able to hold it back for good (its continuous rating).
  Require(std::isfinite(e.push_force) && e.push_force > 0.0 &&
              e.push_force < e.spec.max_continuous_force,
          "push force must be positive and below the device's continuous force rating");
  Require(std::isfinite(e.horizon) && e.horizon > 0.0, "horizon must be positive");
  Require(e.substeps >= 1 && e.substeps <= 10000, "substeps must be in 1..10000");
  period_ = 1.0 / e.rate;
  ticks_ = static_cast<std::uint64_t>(std::ceil(e.horizon * e.rate));
  Require(ticks_ <= 100'000'000, "horizon x rate is more than 1e8 ticks");

  SafetySettings settings;
  settings.force_scale = e.force_scale;
  settings.coupling =
      e.method == RenderingMethod::kDirect ? CouplingMode::kDirect : CouplingMode::kSpringDamper;
  chain_.Configure(settings, e.spec, period_);

  h_ = period_ / e.substeps;
  b_ = e.spec.damping;
  m_ = e.hand_mass;
  decay_ = std::exp(-b_ * h_ / m_);
  coupled_ = e.method == RenderingMethod::kCoupled;
}

void SampledHand::Require(bool ok, const std::string& what) const {
  if (!ok) throw UserError(name_ + ": " + what);
}

double SampledHand::StaticStiffness(double k) const {
  if (!coupled_) return k;
  const double kc = chain_.report().coupling_gains.stiffness;
  return kc * k / (kc + k);
}

}  // namespace fitfeel
