#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "framework/core/export.h"
#include "framework/core/wrench.h"
#include "framework/device/device.h"
#include "framework/runtime/part_state.h"
#include "framework/safety/safety_chain.h"

namespace fitfeel {

// How the contact reaches the device.
enum class RenderingMethod {
  kDirect,   // the contact force, scaled and limited, goes to the device (SafetyChain, direct)
  kCoupled,  // through the virtual coupling of the safety chain (SafetyChain, spring_damper)
};

// "direct" / "coupled" (the CSV's method column).
FITFEEL_API std::string ToString(RenderingMethod method);

// The hand on the device that the stability experiments push into a contact (wall_experiment.h,
// stiction_experiment.h). The hand is continuous: a mass m with the device's physical damping b
// (spec.damping), pushed along +y by a constant force. The rendering is sampled: every
// T = 1 / rate the contact reads the position of the point it acts on (the hand for direct
// rendering, the coupling's proxy otherwise), hands its force to a real SafetyChain, and the
// chain's device force is held constant over the period (zero-order hold). Between samples the
// hand's linear ODE m v' = F + F_push - b v is solved exactly at `substeps` points per period, at
// which the energy and the peak force are sampled.
struct HandExperiment {
  RenderingMethod method = RenderingMethod::kDirect;
  DeviceSpec spec;           // physical damping b and the force limits
  double rate = 1000.0;      // Hz, 1 / T
  double force_scale = 1.0;  // device N per physical N
  // Hand (fingers, handle and linkage) mass. A stylus held in a pen grip moves a fraction of the
  // hand; 0.2 kg sits inside the 0.05-1 kg range the tests sweep. To first order in T the
  // passivity bound does not depend on it (the tests show it over that range).
  double hand_mass = 0.2;  // kg
  // A steady push well inside every listed device's continuous force rating (0.88 N for the
  // Touch and Omni would saturate only beyond it): 0.5 N.
  double push_force = 0.5;  // device N along +y
  double horizon = 2.0;     // s
  int substeps = 50;
  // Coupled only: tell the chain the contact's stiffness (SafetyChain::SetEnvironmentStiffness).
  // Without it the coupling estimates it from the proxy's motion, the harder case.
  bool stiffness_hint = false;
};

// One run of a HandExperiment: the checks both experiments make, the chain, and the sampled loop
// with the hand's exact motion between samples. Not exported: the experiments' own code.
class SampledHand {
 public:
  // Checks the shared parameters and configures the chain. Refusals are UserErrors that start
  // with `name` ("stiction experiment: rate must be positive").
  SampledHand(const HandExperiment& experiment, std::string name);

  // Refuses, as the constructor does, unless `ok`: for an experiment's own parameters.
  void Require(bool ok, const std::string& what) const;

  double period() const { return period_; }
  SafetyChain& chain() { return chain_; }

  // The static stiffness the hand feels against a contact of stiffness k at the device: k for
  // direct rendering, k in series with the coupling's spring otherwise.
  double StaticStiffness(double k) const;

  struct Result {
    double y = 0.0;             // hand position at the end, m
    double v = 0.0;             // hand velocity at the end, m/s
    double final_energy = 0.0;  // the largest energy(y, v) over the last tenth of the horizon
    double peak_force = 0.0;    // largest |device force|, N
    std::uint64_t ticks = 0;
    std::uint64_t non_finite = 0;  // device forces that were not finite (sent as 0)
  };

  // Runs from position y and velocity v to the horizon. Per sample, contact(k, device, law)
  // returns the physical force along y at the state the chain lets the contact see (`law`; the
  // hand's own is `device`), and may set the chain's stiffness hint. After each substep,
  // substep(f, y0, y) with the device force f held over it and the hand's position before and
  // after; energy(y, v) is what the final energy takes the largest of.
  template <class Contact, class Substep, class Energy>
  Result Run(double y, double v, Contact&& contact, Substep&& substep, Energy&& energy);

 private:
  // The hand between two samples: m v' = f - b v with f constant, solved exactly. Inline: the
  // loop calls it `substeps` times a sample.
  void Advance(double force, double* y, double* v) const {
    if (b_ > 0.0) {
      const double v_inf = force / b_;
      const double dv = *v - v_inf;
      *y += v_inf * h_ + dv * (m_ / b_) * (1.0 - decay_);
      *v = v_inf + dv * decay_;
    } else {
      *y += *v * h_ + 0.5 * force / m_ * h_ * h_;
      *v += force / m_ * h_;
    }
  }

  std::string name_;
  double push_force_ = 0.0;
  double horizon_ = 0.0;
  int substeps_ = 1;
  double period_ = 0.0;
  std::uint64_t ticks_ = 0;
  double h_ = 0.0;      // substep, s
  double b_ = 0.0;      // the device's physical damping, N*s/m
  double m_ = 0.0;      // the hand's mass, kg
  double decay_ = 1.0;  // exp(-b h / m)
  bool coupled_ = false;
  SafetyChain chain_;
};

// The final energy is the largest E over the last tenth of the horizon. E does not oscillate at
// twice the frequency the way the kinetic energy alone does, and the window's maximum does not
// depend on where in a cycle the run ends.
inline constexpr double kFinalWindowShare = 0.1;

template <class Contact, class Substep, class Energy>
SampledHand::Result SampledHand::Run(double y, double v, Contact&& contact, Substep&& substep,
                                     Energy&& energy) {
  Result out;
  const double final_window_start = horizon_ * (1.0 - kFinalWindowShare);
  PartState device;
  PartState law_state;
  Wrench physical;
  for (std::uint64_t k = 0; k < ticks_; ++k) {
    const double t = static_cast<double>(k) * period_;
    device.time = t;
    device.position = Eigen::Vector3d(0.0, y, 0.0);
    device.velocity = Eigen::Vector3d(0.0, v, 0.0);
    if (k == 0) chain_.Reset(device);
    chain_.SimulatedState(device, &law_state);
    physical.SetZero();
    physical.force.y() = contact(k, device, law_state);
    double f = chain_.Apply(physical, device, period_).force.y();
    if (!std::isfinite(f)) {
      ++out.non_finite;
      f = 0.0;
    }
    out.peak_force = std::max(out.peak_force, std::abs(f));
    for (int s = 1; s <= substeps_; ++s) {
      const double y0 = y;
      Advance(f + push_force_, &y, &v);
      substep(f, y0, y);
      if (t + period_ * s / substeps_ >= final_window_start) {
        out.final_energy = std::max(out.final_energy, energy(y, v));
      }
    }
    ++out.ticks;
  }
  out.y = y;
  out.v = v;
  return out;
}

}  // namespace fitfeel
