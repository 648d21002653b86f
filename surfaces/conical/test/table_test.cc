// The tabulated analyzer against the per-tick scan it replaces (the scan is the model; the table
// only changes how fast it is evaluated): at the depth steps within the table's stated
// interpolation bound, between them within 2 % of the scan's interference volume, and bit for bit
// the same tables whatever the number of prepare threads.
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/testing/assembly_space_check.h"
#include "surfaces/common/test/column_table_checks.h"

#include "surfaces/conical/conical_contact_analyzer.h"
#include "surfaces/conical/conical_discretizer.h"
#include "surfaces/conical/conical_generator.h"
#include "surfaces/conical/test/test_parts.h"

namespace fitfeel::conical {
namespace {

// The taper-pin scenario's parts (h10 / H10, ground pin, reamed hole), one seed.
void Prepare(ConicalContactAnalyzer* analyzer, std::uint64_t seed, Resolution r = {20, 72},
             TextureMode texture = TextureMode::kExpected) {
  PartSpec pin = test::Pin();
  PartSpec hole = test::Hole();
  pin.size.lower_deviation = -58e-6;
  hole.size.upper_deviation = 58e-6;
  pin.form.tolerance[FormCharacteristic::kRoundness] = 6e-6;
  pin.form.tolerance[FormCharacteristic::kGeneratrixStraightness] = 9e-6;
  hole.form.tolerance[FormCharacteristic::kRoundness] = 9e-6;
  hole.form.tolerance[FormCharacteristic::kGeneratrixStraightness] = 15e-6;
  pin.texture = {0.0, 0.8e-6, 3.2e-6};
  hole.texture = {0.0, 1.6e-6, 6.4e-6};
  ModelSettings settings;
  settings.friction = 0.15;
  settings.contact_stiffness = 1e6;
  settings.texture = texture;
  Rng rng(seed);
  const SkinModelShape pin_sms = ConicalVariationGenerator().Generate(
      pin, ConicalDiscretizer().Discretize(pin, r), texture, rng);
  const SkinModelShape hole_sms = ConicalVariationGenerator().Generate(
      hole, ConicalDiscretizer().Discretize(hole, r), texture, rng);
  analyzer->Prepare(pin, pin_sms, hole, hole_sms, settings);
}

// Offsets that put the pin anywhere from clear of the hole to tens of um into it at depth s.
MatingPose RandomPose(std::mt19937_64& rng, double depth, double clearance) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), reach(0.0, 1.0);
  const double e = std::max(clearance, 0.0) + 30e-6 * reach(rng) - 10e-6;
  const double a = angle(rng);
  MatingPose pose;
  pose.depth = depth;
  pose.offset = std::max(e, 0.0) * Eigen::Vector2d(std::cos(a), std::sin(a));
  return pose;
}

TEST(ConicalTable, EqualsTheScanAtTheDepthStepsWithinItsBound) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    ConicalContactAnalyzer analyzer;
    Prepare(&analyzer, seed);
    std::mt19937_64 rng(100 + seed);
    const double step = analyzer.depth_step();
    for (int k = 1; k < analyzer.table().steps() - 1; k += 3) {
      const double depth = k * step;
      const double bound = test_support::TableVolumeBound(analyzer.table(), k);
      for (int trial = 0; trial < 20; ++trial) {
        const MatingPose pose = RandomPose(rng, depth, analyzer.scan().Clearance(depth));
        const auto [table, scan] = test_support::ExpectTableWithin(
            analyzer, pose, bound,
            "seed " + std::to_string(seed) + " depth " + std::to_string(depth));
        ASSERT_EQ(table.engaged, scan.engaged);
        EXPECT_NEAR(table.engaged_area, scan.engaged_area, 1e-12 * scan.engaged_area);
      }
    }
  }
}

TEST(ConicalTable, BetweenTheStepsStaysWithinTwoPercentOfTheScan) {
  double worst = 0.0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    ConicalContactAnalyzer analyzer;
    Prepare(&analyzer, seed);
    std::mt19937_64 rng(200 + seed);
    std::uniform_real_distribution<double> depth(0.0, 60e-3);
    for (int trial = 0; trial < 400; ++trial) {
      const double s = depth(rng);
      const MatingPose pose = RandomPose(rng, s, analyzer.scan().Clearance(s));
      const double error = test_support::TableRelativeError(analyzer, pose);
      worst = std::max(worst, error);
      EXPECT_LT(error, 0.02) << "seed " << seed << " depth " << s;
    }
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

// The engaged area the tick reads in closed form is the sum of the rows' slant areas the scan and
// the table's cells are built from, at every depth from before the hole to past its end (a pin
// of 20 rows, the hole's rows and columns the cells' own).
TEST(ConicalTable, EngagedAreaIsTheRowsSum) {
  ConicalContactAnalyzer analyzer;
  Prepare(&analyzer, 3, {20, 36});
  const ConicalScanAnalyzer& scan = analyzer.scan();
  std::vector<ColumnCell> cells;
  int engaged = 0;
  for (double depth = -1e-3; depth <= 0.065; depth += 0.37e-3) {
    double rows = 0.0;
    for (int j = 0; j < 36; ++j) {
      scan.ColumnCells(depth, j, &cells);
      for (const ColumnCell& c : cells) rows += c.area;
    }
    EXPECT_NEAR(scan.EngagedArea(depth), rows, 1e-12 * std::max(rows, 1e-9)) << depth;
    engaged += rows > 0.0 ? 1 : 0;
  }
  EXPECT_GT(engaged, 100);
}

TEST(ConicalTable, IsTheSameBitForBitOnOneOrTwoThreads) {
  test_support::ExpectSameTablesOnOneOrTwoThreads<ConicalContactAnalyzer>(
      [](ConicalContactAnalyzer* analyzer) { Prepare(analyzer, 3); },
      [depth = std::uniform_real_distribution<double>(0.0, 60e-3)](
          std::mt19937_64& rng, const ConicalContactAnalyzer& analyzer) mutable {
        const double s = depth(rng);
        return RandomPose(rng, s, analyzer.scan().Clearance(s));
      });
}

// The assembly space (what the viewer draws) is exactly the pin's contact-free offsets: with sharp
// contact, the scan touches nothing just inside the polygon and something just beyond each vertex.
TEST(ConicalAssemblySpace, HoldsExactlyTheContactFreeOffsets) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    ConicalContactAnalyzer analyzer;
    Prepare(&analyzer, seed, {20, 72}, TextureMode::kSampled);
    for (const double depth : {2e-3, 9e-3, 17e-3}) {
      MatingPose pose;
      pose.depth = depth;
      std::vector<Eigen::Vector2d> polygon;
      ASSERT_TRUE(analyzer.AssemblySpace(pose, &polygon));
      ASSERT_GE(polygon.size(), 3u) << "seed " << seed << " depth " << depth;
      test_support::ExpectPolygonIsTheContactFreeSpace(
          analyzer.scan(), pose, polygon,
          "seed " + std::to_string(seed) + " depth " + std::to_string(depth));
    }
  }
}

// Before the pin's small end reaches the hole nothing is engaged: an empty polygon, described.
TEST(ConicalAssemblySpace, IsEmptyBeforeEngagement) {
  ConicalContactAnalyzer analyzer;
  Prepare(&analyzer, 1);
  MatingPose pose;
  pose.depth = -1e-3;
  std::vector<Eigen::Vector2d> polygon = {{1.0, 1.0}};
  EXPECT_TRUE(analyzer.AssemblySpace(pose, &polygon));
  EXPECT_TRUE(polygon.empty());
}

}  // namespace
}  // namespace fitfeel::conical
