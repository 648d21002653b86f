#include <cmath>
#include <numbers>

#include "framework/core/error.h"
#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/cylindrical_law.h"
#include "surfaces/cylindrical/test/contact_test_support.h"

// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace fitfeel::cylindrical {
namespace {

using namespace testing;

Wrench Apply(const ContactAnalyzer& analyzer, const ResistanceLaw& law, double depth,
             Eigen::Vector2d offset, double velocity) {
  MatingPose pose;
  pose.depth = depth;
  pose.offset = offset;
  ContactState s;
  analyzer.Evaluate(pose, &s);
  MatingMotion motion;
  motion.velocity.y() = velocity;
  Wrench w;
  law.Evaluate(s, motion, &w);
  return w;
}

// docs/oracles.md: E = 210 GPa, nu = 0.3, d1 = 20, d2 = 30, L = 20 mm, delta = 1 um radial,
// mu = 0.15 -> p = 5.8333 MPa, F = 1099.6 N. Uniform interference skin model shapes (no form, no
// texture) through analyzer and law; the 20 mm bushing is fully engaged from 20 to 40 mm.
TEST(GpsLaw, LamePressFitOracle) {
  PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  CylinderContactAnalyzer a;
  a.Prepare(shaft, MakeSms(MakeGrid(40, 72, 0.020, 0.040), [](int, int) { return 1 * kUm; }),
            bushing, MakeSms(MakeGrid(25, 72, 0.020, 0.020), [](int, int) { return 0.0; }),
            Settings(0.15, 0.0, TextureMode::kExpected));
  GpsLaw law;
  law.Prepare(shaft, bushing, Settings(0.15));
  EXPECT_NEAR(law.pressure_per_interference() * 1 * kUm, 5.8333e6, 0.001 * 5.8333e6);
  for (double depth : {20.5e-3, 27.3e-3, 39.9e-3}) {
    const Wrench w = Apply(a, law, depth, {0, 0}, 0.010);
    EXPECT_NEAR(w.force.y(), -1099.6, 0.001 * 1099.6) << depth;  // within 0.1 %
    EXPECT_NEAR(w.force.x(), 0.0, 1e-6);
    EXPECT_NEAR(w.force.z(), 0.0, 1e-6);
  }
  // Eq. 12: off the energy-minimising axis (here the bore's axis) a radial spring pushes back,
  // and its force adds to the normal load of the friction.
  GpsLaw stiff;
  stiff.Prepare(shaft, bushing, Settings(0.15, 1e8));
  const Wrench off = Apply(a, stiff, 30e-3, {0.0, 1 * kUm}, 0.010);
  EXPECT_NEAR(off.force.z(), -100.0, 1e-6);
  EXPECT_NEAR(off.force.x(), 0.0, 1e-6);
  EXPECT_NEAR(off.force.y(), -1099.6 - 0.15 * 100.0, 0.001 * 1099.6);
  // k_p left at 0: the Lame radial stiffness of the engaged length, P * pi * d1 * L / 2
  // = 5.8333e12 * pi * 0.02 * 0.02 / 2 = 3.665e9 N/m at full engagement, half at half.
  const double k_full = 5.8333e12 * kPi * 0.020 * 0.020 / 2;
  EXPECT_NEAR(Apply(a, law, 30e-3, {0.0, 1 * kUm}, 0.010).force.z(), -k_full * 1e-6,
              1e-4 * k_full * 1e-6);
  EXPECT_NEAR(Apply(a, law, 10e-3, {0.0, 1 * kUm}, 0.010).force.z(), -k_full * 0.5e-6,
              1e-4 * k_full * 1e-6);
  // Linear in the engaged length while entering and leaving; opposite when pulled out.
  EXPECT_NEAR(Apply(a, law, 10e-3, {0, 0}, 0.010).force.y(), -1099.6 / 2, 0.001 * 1099.6);
  EXPECT_NEAR(Apply(a, law, 50e-3, {0, 0}, -0.010).force.y(), 1099.6 / 2, 0.001 * 1099.6);
  // Linear in delta.
  CylinderContactAnalyzer b;
  b.Prepare(shaft, MakeSms(MakeGrid(40, 72, 0.020, 0.040), [](int, int) { return 2.5 * kUm; }),
            bushing, MakeSms(MakeGrid(25, 72, 0.020, 0.020), [](int, int) { return 0.0; }),
            Settings(0.15, 0.0, TextureMode::kExpected));
  EXPECT_NEAR(Apply(b, law, 30e-3, {0, 0}, 0.010).force.y(), -2.5 * 1099.6, 0.0025 * 1099.6);
}

TEST(GpsLaw, HollowShaftAndTubeInTube) {
  // Hollow shaft, bore 10 mm: c_shaft = (400+100)/(400-100) - 0.3 = 1.36667, c_hub = 2.9.
  PressFitDimensions d{0.020, 0.030, 0.010};
  const double expected = (2e-6 / 0.020) / ((1.366667 + 2.9) / 210e9);
  EXPECT_NEAR(LamePressurePerInterference(d, Steel(), Steel()) * 1e-6, expected, 1e-6 * expected);
  // The oracle's tube in tube: r 25 / 12.5 / 37.5 mm, 0.01 mm radial, E = 207 GPa -> 19.41 MPa.
  const Material m{"steel", 207e9, 0.3};
  EXPECT_NEAR(LamePressurePerInterference({0.050, 0.075, 0.025}, m, m) * 1e-5, 19.41e6, 0.01e6);
  // Dropping the shaft's term would be 24 % high: ours is not.
  EXPECT_NEAR(LamePressurePerInterference({0.020, 0.030, 0.0}, Steel(), Steel()) * 1e-6 / 5.8333e6,
              1.0, 1e-4);
  // Through analyzer and law, hollow shaft, 1 um: F = mu * p * pi * d1 * L.
  PartSpec shaft = MakeShaft(0.020, 0.040, 0.010), bushing = MakeBushing(0.020, 0.020, 0.030);
  CylinderContactAnalyzer a;
  a.Prepare(shaft, MakeSms(MakeGrid(40, 36, 0.020, 0.040), [](int, int) { return 1 * kUm; }),
            bushing, MakeSms(MakeGrid(20, 36, 0.020, 0.020), [](int, int) { return 0.0; }),
            Settings(0.15, 0.0, TextureMode::kSampled));
  GpsLaw law;
  law.Prepare(shaft, bushing, Settings(0.15));
  const double force = 0.15 * expected * kPi * 0.020 * 0.020;
  EXPECT_NEAR(Apply(a, law, 30e-3, {0, 0}, 0.010).force.y(), -force, 1e-3 * force);
}

// A clearance fit without form error under a radial load W gives exactly mu * W.
TEST(Laws, ClearanceUnderRadialLoadGivesMuW) {
  PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  const double c = 10 * kUm, kp = 2e6, weight = 2.0;
  CylinderContactAnalyzer a;
  a.Prepare(shaft, MakeSms(MakeGrid(40, 72, 0.020, 0.040), [](int, int) { return -4 * kUm; }),
            bushing, MakeSms(MakeGrid(20, 72, 0.020, 0.020), [](int, int) { return 6 * kUm; }),
            Settings(0.15, kp, TextureMode::kSampled));
  GpsLaw gps;
  gps.Prepare(shaft, bushing, Settings(0.15, kp));
  // The shaft rests on the bottom (-z, a column direction) where the spring carries its weight.
  const Eigen::Vector2d rest(0.0, -(c + weight / kp));
  for (double depth : {3e-3, 20e-3, 45e-3}) {
    const Wrench w = Apply(a, gps, depth, rest, 0.010);
    EXPECT_NEAR(w.force.z(), weight, 1e-9);
    // Exact up to the friction smoothing: tanh(10 mm/s / 1 mm/s) = 1 - 4.1e-9.
    EXPECT_NEAR(w.force.y(), -0.15 * weight, 0.15 * weight * 5e-9) << depth;
  }
  // VE1 on the same scene: ideal geometry (zero nominal clearance), same mu * W.
  Ve1Law ve1;
  ve1.Prepare(shaft, bushing, Settings(0.15, kp));
  const Wrench w = Apply(a, ve1, 20e-3, {0.0, -weight / kp}, 0.010);
  EXPECT_NEAR(w.force.z(), weight, 1e-9);
  EXPECT_NEAR(w.force.y(), -0.15 * weight, 0.15 * weight * 5e-9);
  // Not engaged: nothing.
  EXPECT_EQ(Apply(a, ve1, -1e-3, {0.0, -weight / kp}, 0.010).force.norm(), 0.0);
}

TEST(Laws, FrictionIsContinuousThroughZeroVelocity) {
  PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  CylinderContactAnalyzer a;
  a.Prepare(shaft, MakeSms(MakeGrid(10, 12, 0.020, 0.040), [](int, int) { return 1 * kUm; }),
            bushing, MakeSms(MakeGrid(5, 12, 0.020, 0.020), [](int, int) { return 0.0; }),
            Settings(0.15, 0.0, TextureMode::kSampled));
  GpsLaw law;
  law.Prepare(shaft, bushing, Settings(0.15));
  double previous = Apply(a, law, 30e-3, {0, 0}, -5 * kFrictionSmoothingVelocity).force.y();
  EXPECT_GT(previous, 0.0);  // opposes motion
  double max_jump = 0.0;
  const int samples = 1000;
  for (int s = 1; s <= samples; ++s) {
    const double v = kFrictionSmoothingVelocity * (-5.0 + 10.0 * s / samples);
    const double f = Apply(a, law, 30e-3, {0, 0}, v).force.y();
    EXPECT_LE(f, previous + 1e-9);  // monotone
    max_jump = std::max(max_jump, std::abs(f - previous));
    previous = f;
  }
  // Lipschitz: slope mu*N/v_s at zero, over a velocity step of 0.01 v_s.
  EXPECT_LT(max_jump, 0.011 * 1099.6 / 2 * 2);
  EXPECT_EQ(Apply(a, law, 30e-3, {0, 0}, 0.0).force.y(), 0.0);
}

// A bushing whose rows close in from 4 um clearance to 5.5 um interference: the force along the
// insertion must have no jump at the clearance / interference boundary (or anywhere): halving the
// sampling step must halve the largest change between samples.
TEST(Laws, ForceIsContinuousAcrossTheInterferenceBoundary) {
  PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  const TextureSpec t{3.2 * kUm, 0.4 * kUm, 1.6 * kUm};
  shaft.texture = t;
  bushing.texture = t;
  CylinderContactAnalyzer a;
  a.Prepare(shaft, MakeSms(MakeGrid(40, 36, 0.020, 0.040), [](int, int) { return 0.0; }), bushing,
            MakeSms(MakeGrid(20, 36, 0.020, 0.020),
                    [](int k, int j) { return (4.0 - 0.5 * k + 0.2 * std::cos(j)) * kUm; }),
            Settings(0.15, 2e7, TextureMode::kExpected));
  GpsLaw law;
  law.Prepare(shaft, bushing, Settings(0.15, 2e7));
  const Eigen::Vector2d x(0.0, -1 * kUm);
  auto largest_jump = [&](double dd, bool* saw_both) {
    double worst = 0.0;
    bool clear = false, interfere = false;
    Wrench prev = Apply(a, law, 4e-3, x, 0.010);
    for (double depth = 4e-3 + dd; depth < 14e-3; depth += dd) {
      MatingPose pose;
      pose.depth = depth;
      pose.offset = x;
      ContactState s;
      a.Evaluate(pose, &s);
      (s.interference ? interfere : clear) = true;
      const Wrench w = Apply(a, law, depth, x, 0.010);
      worst = std::max(worst, (w.force - prev.force).norm());
      prev = w;
    }
    *saw_both = clear && interfere;
    return worst;
  };
  bool both = false;
  const double step = a.depth_step();
  const double coarse = largest_jump(step / 50, &both);
  EXPECT_TRUE(both);
  const double fine = largest_jump(step / 100, &both);
  EXPECT_GT(coarse, 0.0);
  EXPECT_LT(fine, 0.6 * coarse);
}

TEST(Laws, RefuseNonCylindricalParts) {
  PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  PartSpec bare = bushing;
  bare.geometry.reset();
  GpsLaw law;
  EXPECT_THROW(law.Prepare(shaft, bare, Settings()), UserError);
  PartSpec thin = MakeBushing(0.020, 0.020, 0.019);
  EXPECT_THROW(law.Prepare(shaft, thin, Settings()), UserError);
  PartSpec soft = bushing;
  soft.material.youngs_modulus = 0.0;
  Ve1Law ve1;
  EXPECT_THROW(ve1.Prepare(shaft, soft, Settings()), UserError);
}

}  // namespace
}  // namespace fitfeel::cylindrical
