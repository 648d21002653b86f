// Stick-slip on the cone (framework/model/friction.h): a pin pressed in and released stays in when
// tan(alpha) < mu_s (self-locking, DIN 7190 / any machine-elements text: the wedge force
// N sin(alpha) is below what friction holds, mu_s N cos(alpha)), and slides out when it is not.
// And the DIN 7190 elastic limit of the hub at its mean diameter.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "framework/core/wrench.h"
#include "framework/model/elastic_limit.h"
#include "framework/model/friction.h"
#include "surfaces/conical/conical_contact_analyzer.h"
#include "surfaces/conical/conical_discretizer.h"
#include "surfaces/conical/conical_generator.h"
#include "surfaces/conical/conical_law.h"
#include "surfaces/conical/test/test_parts.h"

namespace fitfeel::conical {
namespace {

using test::kHoleLength;

PartSpec Pin(double taper) {
  PartSpec p = test::Pin();
  p.geometry = std::make_shared<ConicalGeometry>(Role::kInner, 8e-3, 40e-3, taper, 0.0);
  return p;
}

PartSpec Hole(double taper) {
  PartSpec p = test::Hole();
  p.geometry = std::make_shared<ConicalGeometry>(Role::kOuter, 8e-3, kHoleLength, taper, 30e-3);
  return p;
}

struct LockingModel {
  ConicalContactAnalyzer analyzer;
  TaperPressFitLaw law;
  LawState state;

  LockingModel(double taper, double mu, double pin_yield = 0.0, double hub_yield = 0.0) {
    PartSpec pin = Pin(taper), hole = Hole(taper);
    pin.material.yield_strength = pin_yield;
    hole.material.yield_strength = hub_yield;
    ModelSettings settings;
    settings.friction = mu;
    settings.static_friction = mu;
    settings.contact_stiffness = 1e6;
    settings.resolution = Resolution{10, 36};
    Rng rng(1);
    const ConicalDiscretizer discretizer;
    const ConicalVariationGenerator generator;
    const SkinModelShape pin_sms = generator.Generate(
        pin, discretizer.Discretize(pin, settings.resolution), TextureMode::kExpected, rng);
    const SkinModelShape hole_sms = generator.Generate(
        hole, discretizer.Discretize(hole, settings.resolution), TextureMode::kExpected, rng);
    analyzer.Prepare(pin, pin_sms, hole, hole_sms, settings);
    law.Prepare(pin, hole, settings);
  }

  // The pin at `depth`, the run's friction advanced to it.
  Wrench At(double depth, ContactState* contact_out = nullptr) {
    MatingPose pose;
    pose.depth = depth;
    ContactState contact;
    analyzer.Evaluate(pose, &contact);
    MatingMotion motion;
    motion.depth = depth;
    Wrench w;
    law.Evaluate(contact, motion, &state, &w);
    if (contact_out != nullptr) *contact_out = contact;
    return w;
  }

  // Presses the pin `advance` past seating in 10 um steps, then lets go: with no push the pin
  // moves wherever the contact's axial force drives it, quasi-statically (steps of 20 nm, far
  // below the junctions' 2 um). Returns how far it backed out, up to `limit`.
  double PressAndRelease(double advance, double limit) {
    double depth = kHoleLength - 50e-6;
    while (depth < kHoleLength + advance) At(depth += 10e-6);
    const double pressed = depth;
    while (pressed - depth < limit && At(depth).force.y() < 0.0) depth -= 20e-9;
    return pressed - depth;
  }
};

// Released after pressing, the junctions' deflection (z_s = 2 um along the generatrix, pressing
// in) unloads and reverses until it carries the wedge: s = z_s (1 + tan(alpha) / mu_s), i.e. the
// pin backs out by s / cos(alpha) and holds there.
double Backlash(double tan_alpha, double mu) {
  return kSteelBreakawayDisplacement * (1.0 + tan_alpha / mu) / std::cos(std::atan(tan_alpha));
}

TEST(ConicalStickSlip, SelfLockingTaperStaysInWhenReleased) {
  // 1:50 (ISO 2339 taper pins): tan(alpha) = 0.01 against mu = 0.15.
  LockingModel pin(1.0 / 50.0, 0.15);
  EXPECT_NEAR(pin.PressAndRelease(0.2e-3, 200e-6), Backlash(0.01, 0.15), 40e-9);
  // 1:5 (tan(alpha) = 0.1) is still self-locking with mu = 0.15 ...
  LockingModel steep(1.0 / 5.0, 0.15);
  EXPECT_NEAR(steep.PressAndRelease(0.05e-3, 200e-6), Backlash(0.1, 0.15), 40e-9);
}

TEST(ConicalStickSlip, TaperSteeperThanItsFrictionAngleSlidesOut) {
  // ... but not with mu = 0.05 < tan(alpha) = 0.1: released, the wedge drives it out.
  LockingModel steep(1.0 / 5.0, 0.05);
  EXPECT_GE(steep.PressAndRelease(0.05e-3, 20e-6), 20e-6);
}

TEST(ConicalStickSlip, PressingSlidesAtCoulombTheDin7190Force) {
  // Stick-slip gives DIN 7190's press-in force F = p pi dm L (mu + tan alpha) while sliding.
  LockingModel pin(1.0 / 50.0, 0.15);
  double depth = kHoleLength;
  Wrench w;
  for (int i = 0; i < 20; ++i) w = pin.At(depth += 10e-6);
  const double advance = depth - kHoleLength;
  const double dm = 8.2e-3, delta = 0.5 * advance / 50.0, E = 210e9, nu = 0.3, d2 = 30e-3;
  const double p =
      (2.0 * delta / dm) / ((1.0 - nu) / E + ((d2 * d2 + dm * dm) / (d2 * d2 - dm * dm) + nu) / E);
  EXPECT_NEAR(-w.force.y(), p * M_PI * dm * kHoleLength * (0.15 + 0.01), 1e-6 * std::abs(w.force.y()));
  EXPECT_TRUE(pin.state.friction.sliding);
}

TEST(ConicalElasticLimit, HubAtItsMeanDiameterPerDin7190) {
  // C45 +QT hub (R_e 430 MPa, EN 10083-2, 16-40 mm) on a hardened pin (R_e 2 GPa, so that the
  // hub governs): p_F = (1 - Q^2) R_e / sqrt(3), Q = dm / D = 8.2 / 30.
  LockingModel pin(1.0 / 50.0, 0.15, 2000e6, 430e6);
  const double q = 8.2 / 30.0, p_f = (1.0 - q * q) * 430e6 / std::sqrt(3.0);
  EXPECT_NEAR(HubYieldPressure(8.2e-3, 30e-3, 430e6), p_f, 1e-6 * p_f);
  ContactState contact;
  pin.At(kHoleLength + 0.5e-3, &contact);  // 5 um radial interference all along
  const ElasticLimitCheck check = pin.law.CheckElasticLimit(contact);
  const double p = pin.law.PressurePerInterference() * 5e-6;
  EXPECT_EQ(check.part, 1);
  EXPECT_NEAR(check.utilisation, p / p_f, 1e-9);
  // Far enough to pass it: the advance at which p reaches p_f, and 10 % beyond.
  const double yield_advance = 2.0 * 50.0 * p_f / pin.law.PressurePerInterference();
  pin.At(kHoleLength + 1.1 * yield_advance, &contact);
  EXPECT_NEAR(pin.law.CheckElasticLimit(contact).utilisation, 1.1, 1e-6);
  // Without a yield strength nothing is checked.
  LockingModel unknown(1.0 / 50.0, 0.15);
  unknown.At(kHoleLength + 0.5e-3, &contact);
  EXPECT_EQ(unknown.law.CheckElasticLimit(contact).utilisation, 0.0);
}

}  // namespace
}  // namespace fitfeel::conical
