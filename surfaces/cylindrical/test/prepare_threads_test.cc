// The depth table is computed in fixed chunks of steps on PrepareThreads() threads: the tables,
// and so every tick, are the same bit for bit on one thread or two (issue: parallel prepare), and
// prepared progressively (ContactAnalyzer::PrepareStart, PrepareAhead, FinishPrepare).
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

#include "surfaces/common/test/column_table_checks.h"
#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/test/contact_test_support.h"

// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace fitfeel::cylindrical {
namespace {

using namespace testing;

// How a test prepares the tables: whole, or progressively, ready to `ready` m, then `ahead`
// steps one at a time (all of them when negative), then (with `finish`) the rest at once.
struct Schedule {
  bool progressive = false;
  double ready = 0.0;
  int ahead = -1;
  bool finish = true;  // false: left after the steps ahead
};

// Lobed random form of a few micrometres on a shaft whose radius grows by `growth` along it from
// `mean`: steps with an assembly space and steps in interference (the Newton or elastic solves)
// both occur.
void PrepareOn(int threads, const std::string& law, double mean, CylinderContactAnalyzer* a,
               const Schedule& schedule = {}, double growth = 8e-6) {
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
  const SkinModelShape inner =
      MakeSms(MakeGrid(40, columns, 0.020, 0.040), lobed(mean, growth, 0.0));
  const SkinModelShape outer = MakeSms(MakeGrid(40, columns, 0.020, 0.020), lobed(0.0, 0.0, 1.0));
  if (!schedule.progressive) {
    a->Prepare(shaft, inner, bushing, outer, settings);
  } else {
    a->PrepareStart(shaft, inner, bushing, outer, settings, nullptr, schedule.ready);
    EXPECT_TRUE(a->prepared());
    EXPECT_GE(a->prepared_depth(), schedule.ready);
    for (int k = 0; (schedule.ahead < 0 || k < schedule.ahead) && a->PrepareAhead(1); ++k) {
    }
    if (schedule.finish) {
      a->FinishPrepare();
      EXPECT_EQ(a->prepared_depth(), std::numeric_limits<double>::infinity());
      EXPECT_FALSE(a->PrepareAhead(1));
    }
  }
  unsetenv("FITFEEL_PREPARE_THREADS");
}

void ExpectSameTables(const std::string& law, double mean, const Schedule& schedule = {},
                      double taper = 8e-6) {
  CylinderContactAnalyzer one, two;
  PrepareOn(1, law, mean, &one, {}, taper);
  PrepareOn(2, law, mean, &two, schedule, taper);
  EXPECT_EQ(one.newton_iterations(), two.newton_iterations());
  EXPECT_EQ(one.max_polygon_vertices(), two.max_polygon_vertices());
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
  // Every step, its axis off the assembly space all round: the polygons' projections and fans.
  for (int k = 0; k + 1 < one.depth_steps(); ++k) {
    for (int q = 0; q < 8; ++q) {
      MatingPose pose;
      pose.depth = (k + 0.25) * one.depth_step();
      pose.offset = 20e-6 * Eigen::Vector2d(std::cos(q * M_PI / 4), std::sin(q * M_PI / 4));
      ContactState a, b;
      one.Evaluate(pose, &a);
      two.Evaluate(pose, &b);
      ASSERT_EQ(a.penetration_direction, b.penetration_direction) << k << " " << q;
      ASSERT_EQ(a.assembly_extent, b.assembly_extent) << k << " " << q;
    }
  }
  std::uniform_real_distribution<double> depth(0.0, 0.060), offset(-4e-6, 4e-6);
  test_support::ExpectSameTicks(one, two, [&](std::mt19937_64& rng, const auto&) {
    MatingPose pose;
    pose.depth = depth(rng);
    pose.offset = {offset(rng), offset(rng)};
    return pose;
  });
}

TEST(CylinderPrepare, TablesAreTheSameBitForBitOnOneOrTwoThreadsWithTheGpsLaw) {
  ExpectSameTables("gps", -6.0e-6);
}

TEST(CylinderPrepare, TablesAreTheSameBitForBitOnOneOrTwoThreadsWithTheElasticLaw) {
  ExpectSameTables("elastic", -6.0e-6);
}

// Step by step from first contact to the end, as the run's worker prepares them.
TEST(CylinderProgressivePrepare, StepByStepGivesTheWholePreparesTables) {
  ExpectSameTables("gps", -6.0e-6, {.progressive = true, .ready = 1e-3, .ahead = -1});
}

// A shaft whose radius falls along it: the steps interfere while its thick leading rows are in
// the bore and clear once they have passed through, so steps in clearance follow steps in
// interference within one progressive chunk (each step's polygon and fans its own).
TEST(CylinderProgressivePrepare, ClearanceAfterInterferenceGivesTheWholePreparesTables) {
  ExpectSameTables("gps", 2.0e-6, {.progressive = true, .ready = 1e-3, .ahead = -1}, -8e-6);
}

// Ready, a few steps into the second chunk (the elastic solves' warm starts carried across the
// first chunk's end), then the rest on two threads (a run whose ticks end before its worker: the
// rest finished at once).
TEST(CylinderProgressivePrepare, PartWayThenFinishedAtOnceGivesTheWholePreparesTables) {
  ExpectSameTables("elastic", -6.0e-6, {.progressive = true, .ready = 2e-3, .ahead = 37});
  ExpectSameTables("gps", -6.0e-6, {.progressive = true, .ready = 0.0, .ahead = 0});
}

// The parts of a state a law reads, bit for bit.
void ExpectSameState(const ContactState& a, const ContactState& b) {
  EXPECT_EQ(a.engaged_length, b.engaged_length);
  EXPECT_EQ(a.interference, b.interference);
  EXPECT_EQ(a.interference_volume, b.interference_volume);
  EXPECT_EQ(a.pressure_resultant, b.pressure_resultant);
  EXPECT_EQ(a.max_interference, b.max_interference);
  EXPECT_EQ(a.penetration, b.penetration);
  EXPECT_EQ(a.normal_force, b.normal_force);
  EXPECT_EQ(a.tilt, b.tilt);
}

// Past the frontier a pose feels the frontier's state, flagged with how far past it it is; once
// whole, its own.
TEST(CylinderProgressivePrepare, APosePastTheFrontierFeelsTheFrontiersStateHeld) {
  CylinderContactAnalyzer whole, part;
  PrepareOn(1, "gps", -6.0e-6, &whole);
  PrepareOn(1, "gps", -6.0e-6, &part,
            {.progressive = true, .ready = 3e-3, .ahead = 0, .finish = false});
  const double frontier = part.prepared_depth();
  ASSERT_GE(frontier, 3e-3);
  ASSERT_LT(frontier, 3e-3 + 2.0 * part.depth_step());
  MatingPose at;
  at.depth = frontier;
  at.offset = {1e-6, -2e-6};
  MatingPose past = at;
  past.depth = 0.012;
  ContactState held, there, whole_there;
  part.Evaluate(past, &held);
  part.Evaluate(at, &there);
  whole.Evaluate(at, &whole_there);
  EXPECT_EQ(held.held_depth, past.depth - frontier);
  EXPECT_EQ(there.held_depth, 0.0);
  ExpectSameState(held, there);
  ExpectSameState(there, whole_there);  // the frontier's state is the whole table's there

  part.FinishPrepare();
  ContactState own, whole_own;
  part.Evaluate(past, &own);
  whole.Evaluate(past, &whole_own);
  EXPECT_EQ(own.held_depth, 0.0);
  ExpectSameState(own, whole_own);
  EXPECT_NE(own.engaged_length, held.engaged_length);  // the pose's own state, not the frontier's
}

}  // namespace
}  // namespace fitfeel::cylindrical
