#include "framework/safety/safety_chain.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"
#include "framework/testing/units.h"

namespace fitfeel {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using test_support::kInf;

Wrench Force(double x, double y, double z) {
  Wrench w;
  w.force = Eigen::Vector3d(x, y, z);
  return w;
}

SafetySettings Direct(double scale) {
  SafetySettings s;
  s.coupling = CouplingMode::kDirect;
  s.force_scale = scale;
  return s;
}

TEST(SafetyChain, ScalesPhysicalToDeviceNewtonsAndReportsTheScale) {
  SafetyChain chain;
  chain.Configure(Direct(0.01), LookupDeviceSpec("PHANTOM Desktop"), 1e-3);
  const Wrench out = chain.Apply(Force(0.0, -300.0, 100.0), PartState{}, 1e-3);
  EXPECT_DOUBLE_EQ(out.force.y(), -3.0);
  EXPECT_DOUBLE_EQ(out.force.z(), 1.0);
  EXPECT_DOUBLE_EQ(chain.report().force_scale, 0.01);
  EXPECT_DOUBLE_EQ(chain.report().max_physical_force, std::hypot(300.0, 100.0));
  EXPECT_EQ(chain.report().peak_limited_ticks, 0u);
}

// A 3-DOF device at a stated lever arm: the torque about the axis becomes the handle's
// tangential force, scaled and limited like any force; torques about the other axes pass.
TEST(SafetyChain, TorqueAboutTheAxisIsFeltAtTheLeverArm) {
  SafetySettings s = Direct(0.5);
  s.torque_lever = 0.008;
  SafetyChain chain;
  chain.Configure(s, LookupDeviceSpec("PHANTOM Desktop"), 1e-3);
  Wrench w = Force(0.5, -1.0, 0.0);
  w.torque = Eigen::Vector3d(0.001, -0.004, 0.0);
  const Wrench out = chain.Apply(w, PartState{}, 1e-3);
  EXPECT_DOUBLE_EQ(out.force.x(), 0.5 * (0.5 - 0.004 / 0.008));
  EXPECT_DOUBLE_EQ(out.force.y(), -0.5);
  EXPECT_DOUBLE_EQ(out.torque.y(), 0.0);
  EXPECT_DOUBLE_EQ(out.torque.x(), 0.0005);
}

TEST(SafetyChain, PhysicalFullScaleMapsToTheContinuousRating) {
  SafetySettings s = Direct(1.0);
  s.physical_full_scale = 350.0;
  SafetyChain chain;
  chain.Configure(s, LookupDeviceSpec("PHANTOM Desktop"), 1e-3);
  EXPECT_DOUBLE_EQ(chain.force_scale(), 1.75 / 350.0);
  EXPECT_NEAR(chain.Apply(Force(0, -350.0, 0), PartState{}, 1e-3).force.norm(), 1.75, 1e-12);
}

TEST(SafetyChain, SaturatesAtTheDevicePeakForce) {
  SafetyChain chain;
  chain.Configure(Direct(0.01), LookupDeviceSpec("Touch"), 1e-3);
  const Wrench out = chain.Apply(Force(0.0, -5000.0, 0.0), PartState{}, 1e-3);  // 50 N asked
  EXPECT_LE(out.force.norm(), 3.3);
  EXPECT_NEAR(out.force.y(), -3.3, 1e-9);
  EXPECT_EQ(chain.report().peak_limited_ticks, 1u);
  EXPECT_DOUBLE_EQ(chain.report().max_requested_force, 50.0);
  EXPECT_LE(chain.report().max_delivered_force, 3.3);
}

TEST(SafetyChain, NonFiniteNeverReachesTheDevice) {
  SafetyChain chain;
  chain.Configure(Direct(1.0), LookupDeviceSpec("Touch"), 1e-3);
  PartState state;
  Wrench out = chain.Apply(Force(kNaN, 0.0, 0.0), state, 1e-3);
  EXPECT_EQ(out.force, Eigen::Vector3d::Zero());
  EXPECT_EQ(chain.report().non_finite_faults, 1u);
  Wrench torque;
  torque.torque = Eigen::Vector3d(0.0, kInf, 0.0);
  out = chain.Apply(torque, state, 1e-3);
  EXPECT_TRUE(out.AllFinite());
  EXPECT_EQ(out.torque, Eigen::Vector3d::Zero());
  EXPECT_EQ(chain.report().non_finite_faults, 2u);
  state.position.x() = kNaN;
  out = chain.Apply(Force(1.0, 0.0, 0.0), state, 1e-3);
  EXPECT_EQ(out.force, Eigen::Vector3d::Zero());
  EXPECT_EQ(chain.report().non_finite_faults, 3u);
  // A finite input afterwards goes through again.
  state.position.setZero();
  out = chain.Apply(Force(1.0, 0.0, 0.0), state, 1e-3);
  EXPECT_DOUBLE_EQ(out.force.x(), 1.0);
}

TEST(SafetyChain, ReportFormatsWithUnits) {
  SafetyChain chain;
  chain.Configure(SafetySettings{}, LookupDeviceSpec("PHANTOM Desktop"), 1e-3);
  chain.Apply(Force(0.0, 1e4, 0.0), PartState{}, 1e-3);
  const std::string text = FormatSafetyReport(chain.report());
  EXPECT_NE(text.find("force scale: 1 device N per physical N"), std::string::npos) << text;
  EXPECT_NE(text.find("K_c 800 N/m, B_c 2.3 N*s/m"), std::string::npos) << text;
  EXPECT_NE(text.find("peak 7.9 N, continuous 1.75 N"), std::string::npos) << text;
  EXPECT_NE(text.find("ticks: 1 "), std::string::npos) << text;
}

TEST(SafetyChain, UnconfiguredChainSendsNothing) {
  SafetyChain chain;
  EXPECT_EQ(chain.Apply(Force(1.0, 2.0, 3.0), PartState{}, 1e-3).force, Eigen::Vector3d::Zero());
}

TEST(SafetyChain, RefusesCouplingGainsThatBreakTheBound) {
  SafetySettings s;
  s.coupling_stiffness = 900.0;
  s.coupling_damping = 4.9;  // 0.45 + 4.9 > 5
  SafetyChain chain;
  EXPECT_THROW(chain.Configure(s, LookupDeviceSpec("PHANTOM Desktop"), 1e-3), UserError);
  s.coupling_damping = 4.0;
  EXPECT_NO_THROW(chain.Configure(s, LookupDeviceSpec("PHANTOM Desktop"), 1e-3));
  EXPECT_DOUBLE_EQ(chain.report().coupling_gains.stiffness, 900.0);
}

// Property over many seeds: whatever the law and the device report (huge, tiny, NaN, inf), the
// device gets a finite wrench within its peak force, for both couplings.
TEST(SafetyChain, OutputAlwaysFiniteAndWithinLimits) {
  for (CouplingMode mode : {CouplingMode::kDirect, CouplingMode::kSpringDamper}) {
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
      std::mt19937_64 rng(seed);
      std::normal_distribution<double> n(0.0, 1.0);
      std::lognormal_distribution<double> mag(0.0, 4.0);
      std::uniform_int_distribution<int> pick(0, 40);
      SafetySettings s;
      s.coupling = mode;
      s.force_scale = 0.01;
      s.passivity_controller = (seed % 2) == 0;
      const DeviceSpec spec = KnownDeviceSpecs()[seed % KnownDeviceSpecs().size()];
      SafetyChain chain;
      chain.Configure(s, spec, 1e-3);
      PartState state;
      for (int k = 0; k < 1000; ++k) {
        state.position += Eigen::Vector3d(n(rng), n(rng), n(rng)) * 1e-4;
        state.velocity = Eigen::Vector3d(n(rng), n(rng), n(rng)) * 0.05;
        Wrench w;
        w.force = Eigen::Vector3d(n(rng), n(rng), n(rng)) * mag(rng);
        w.torque = Eigen::Vector3d(n(rng), n(rng), n(rng));
        const int p = pick(rng);
        if (p == 0) w.force.x() = kNaN;
        if (p == 1) w.force.y() = -kInf;
        if (p == 2) w.torque.z() = kNaN;
        PartState seen = state;
        if (p == 3) seen.velocity.x() = kNaN;
        const double dt = p == 4 ? kNaN : 1e-3;
        chain.SetEnvironmentStiffness(p == 5 ? kInf : mag(rng) * 1e4);
        const Wrench out = chain.Apply(w, seen, dt);
        ASSERT_TRUE(out.AllFinite()) << "seed " << seed << " tick " << k;
        ASSERT_LE(out.force.norm(), spec.max_force) << "seed " << seed << " tick " << k;
      }
      EXPECT_GT(chain.report().non_finite_faults, 0u);
      EXPECT_LE(chain.report().max_delivered_force, spec.max_force);
    }
  }
}

// A hand (mass 0.1 kg, the device's damping b) pressing 1 N into a wall standing for a press fit:
// 2 N/um physical contact stiffness (the scenario format's example) at force scale 1/100 is
// 20000 N/m at the device, twice Colgate's bound 2 b / T = 10000 N/m for the Desktop. The law is
// evaluated where the chain says (device for direct rendering, proxy when coupled).
struct HandRun {
  double energy_created = 0.0;
  double early_peak_speed = 0.0;
  double late_peak_speed = 0.0;
  double final_penetration = 0.0;  // of the simulated part, m
  double max_force = 0.0;
};

HandRun PressHand(CouplingMode mode, double physical_stiffness, double scale, bool hint) {
  const DeviceSpec spec = LookupDeviceSpec("PHANTOM Desktop");
  SafetySettings s;
  s.coupling = mode;
  s.force_scale = scale;
  SafetyChain chain;
  chain.Configure(s, spec, 1e-3);
  const double mass = 0.1;
  const double hand_force = 1.0;
  PartState device;
  device.position = Eigen::Vector3d(0.0, 0.001, 0.0);  // 1 mm above the wall face at y = 0
  HandRun run;
  const int ticks = 4000;
  for (int k = 0; k < ticks; ++k) {
    device.time = k * 1e-3;
    PartState law_state;
    chain.SimulatedState(device, &law_state);
    const double depth = std::max(0.0, -law_state.position.y());
    Wrench physical;
    physical.force.y() = physical_stiffness * depth;  // the bore pushes the shaft back up
    if (hint) chain.SetEnvironmentStiffness(depth > 0.0 ? physical_stiffness : 0.0);
    const Wrench out = chain.Apply(physical, device, 1e-3);
    run.max_force = std::max(run.max_force, out.force.norm());
    const int substeps = 50;
    const double h = 1e-3 / substeps;
    for (int i = 0; i < substeps; ++i) {
      const Eigen::Vector3d a =
          (out.force + Eigen::Vector3d(0.0, -hand_force, 0.0) - spec.damping * device.velocity) /
          mass;
      device.velocity += h * a;
      device.position += h * device.velocity;
    }
    const double speed = device.velocity.norm();
    if (k >= 500 && k < 1000) run.early_peak_speed = std::max(run.early_peak_speed, speed);
    if (k >= ticks - 500) run.late_peak_speed = std::max(run.late_peak_speed, speed);
    PartState law_after;
    chain.SimulatedState(device, &law_after);
    run.final_penetration = std::max(0.0, -law_after.position.y());
  }
  run.energy_created = chain.report().energy_created;
  return run;
}

TEST(SafetyChain, DirectRenderingOfAPressFitStiffnessCreatesEnergy) {
  // 20000 N/m at the device: K T / 2 = 10 N*s/m > b = 5: active, the observer sees it.
  const HandRun direct = PressHand(CouplingMode::kDirect, 2e6, 0.01, false);
  const HandRun coupled = PressHand(CouplingMode::kSpringDamper, 2e6, 0.01, true);
  std::printf(
      "press fit 2 N/um at 1/100: direct created %.3g J, late peak speed %.3g m/s; "
      "coupled created %.3g J, late peak speed %.3g m/s\n",
      direct.energy_created, direct.late_peak_speed, coupled.energy_created,
      coupled.late_peak_speed);
  EXPECT_GT(direct.energy_created, 1e-4);
  EXPECT_GT(direct.late_peak_speed, 0.01);  // still bouncing after 4 s
}

TEST(SafetyChain, CoupledRenderingOfAPressFitStiffnessStaysPassive) {
  // 2 N/um, and a hundred and ten thousand times stiffer, with and without the stiffness hint.
  for (double stiffness : {2e6, 2e8, 2e10}) {
    for (bool hint : {true, false}) {
      const HandRun coupled = PressHand(CouplingMode::kSpringDamper, stiffness, 0.01, hint);
      EXPECT_LT(coupled.energy_created, 1e-6) << stiffness << " hint " << hint;
      EXPECT_LT(coupled.late_peak_speed, 1e-4) << stiffness << " hint " << hint;  // settled
      EXPECT_LE(coupled.max_force, 7.9);
      // The simulated part rests where the wall carries the hand's 1 N.
      const double depth = 1.0 / (stiffness * 0.01);
      EXPECT_NEAR(coupled.final_penetration, depth, 1e-3 * depth) << stiffness << " hint " << hint;
    }
  }
}

// Sliding friction of the press fit (150 N physical, 1.5 N at scale 1/100) opposing the proxy's
// motion: a hand pushing F through the coupling sticks when F < 1.5 N and otherwise slides at the
// speed where the device's damping takes the rest, (F - 1.5 N) / 5 N*s/m; the rendering creates
// no energy either way.
TEST(SafetyChain, CoupledRenderingOfSlidingFrictionIsPassive) {
  const DeviceSpec spec = LookupDeviceSpec("PHANTOM Desktop");
  for (double hand_force : {1.0, 2.0, 4.0}) {
    SafetySettings s;
    s.force_scale = 0.01;
    SafetyChain chain;
    chain.Configure(s, spec, 1e-3);
    PartState device;
    const double mass = 0.1;
    for (int k = 0; k < 3000; ++k) {
      PartState law;
      chain.SimulatedState(device, &law);
      Wrench friction;
      const double v = law.velocity.y();
      friction.force.y() = v < 0.0 ? 150.0 : (v > 0.0 ? -150.0 : 0.0);
      const Wrench out = chain.Apply(friction, device, 1e-3);
      for (int i = 0; i < 50; ++i) {
        const Eigen::Vector3d a =
            (out.force + Eigen::Vector3d(0.0, -hand_force, 0.0) - spec.damping * device.velocity) /
            mass;
        device.velocity += 2e-5 * a;
        device.position += 2e-5 * device.velocity;
      }
    }
    const double expected = -std::max(0.0, hand_force - 1.5) / spec.damping;
    EXPECT_NEAR(device.velocity.y(), expected, 0.005) << "hand " << hand_force;
    EXPECT_EQ(chain.report().energy_created, 0.0) << "hand " << hand_force;
    EXPECT_EQ(chain.report().non_finite_faults, 0u);
  }
}

}  // namespace
}  // namespace fitfeel
