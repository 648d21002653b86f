// The depth table is computed in fixed chunks of steps on PrepareThreads() threads: the tables,
// and so every tick, are the same bit for bit on one thread or two (issue: parallel prepare).
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/test/contact_test_support.h"

// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace fitfeel::cylindrical {
namespace {

using namespace testing;

// Lobed random form of a few micrometres on a shaft whose radius grows by 8 um along it from
// `mean`: steps with an assembly space and steps in interference (the Newton or elastic solves)
// both occur.
void PrepareOn(int threads, const std::string& law, double mean, CylinderContactAnalyzer* a) {
  setenv("FITFEEL_PREPARE_THREADS", std::to_string(threads).c_str(), 1);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> noise(-1.5e-6, 1.5e-6);
  const int columns = 120;
  // `taper`: the radius grows by this much from the first row to the last (rows of 40).
  auto lobed = [&](double base, double taper, double phase) {
    return [&, base, taper, phase](int i, int j) {
      return base + taper * i / 40.0 + 2e-6 * std::cos(3.0 * (2.0 * M_PI * j / columns) + phase) +
             noise(rng);
    };
  };
  const PartSpec shaft = MakeShaft(0.020, 0.040), bushing = MakeBushing(0.020, 0.020, 0.030);
  ModelSettings settings = Settings(0.15, 0.0, TextureMode::kDin7190);
  settings.law = law;
  a->Prepare(shaft, MakeSms(MakeGrid(40, columns, 0.020, 0.040), lobed(mean, 8e-6, 0.0)), bushing,
             MakeSms(MakeGrid(40, columns, 0.020, 0.020), lobed(0.0, 0.0, 1.0)), settings);
  unsetenv("FITFEEL_PREPARE_THREADS");
}

void ExpectSameTables(const std::string& law, double mean) {
  CylinderContactAnalyzer one, two;
  PrepareOn(1, law, mean, &one);
  PrepareOn(2, law, mean, &two);
  ASSERT_EQ(one.depth_steps(), two.depth_steps());
  int interfering = 0;
  for (int k = 0; k < one.depth_steps(); ++k) {
    ASSERT_EQ(one.interference_at(k), two.interference_at(k)) << k;
    interfering += one.interference_at(k) ? 1 : 0;
    ASSERT_EQ(one.anchor(k), two.anchor(k)) << k;
    ASSERT_EQ(one.normal_force(k), two.normal_force(k)) << k;
    ASSERT_EQ(one.tilt(k), two.tilt(k)) << k;
  }
  // Both kinds of step, or the comparison proves less than it says.
  EXPECT_GT(interfering, 10) << law;
  EXPECT_LT(interfering, one.depth_steps() - 10) << law;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> depth(0.0, 0.060), offset(-4e-6, 4e-6);
  for (int trial = 0; trial < 2000; ++trial) {
    MatingPose pose;
    pose.depth = depth(rng);
    pose.offset = {offset(rng), offset(rng)};
    ContactState a, b;
    one.Evaluate(pose, &a);
    two.Evaluate(pose, &b);
    ASSERT_EQ(a.interference_volume, b.interference_volume) << trial;
    ASSERT_EQ(a.pressure_resultant, b.pressure_resultant) << trial;
    ASSERT_EQ(a.max_interference, b.max_interference) << trial;
    ASSERT_EQ(a.penetration, b.penetration) << trial;
    ASSERT_EQ(a.penetration_direction, b.penetration_direction) << trial;
    ASSERT_EQ(a.normal_force, b.normal_force) << trial;
  }
}

TEST(CylinderPrepare, TablesAreTheSameBitForBitOnOneOrTwoThreadsWithTheGpsLaw) {
  ExpectSameTables("gps", -6.0e-6);
}

TEST(CylinderPrepare, TablesAreTheSameBitForBitOnOneOrTwoThreadsWithTheElasticLaw) {
  ExpectSameTables("elastic", -6.0e-6);
}

}  // namespace
}  // namespace fitfeel::cylindrical
