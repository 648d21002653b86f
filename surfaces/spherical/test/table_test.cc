// The tabulated analyzer against the per-tick scan it replaces (the scan is the model; the table
// only changes how fast it is evaluated): at the rotation steps within the table's stated
// interpolation bound, between them within 2 % of the scan's interference volume, and bit for bit
// the same tables whatever the number of prepare threads.
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/testing/assembly_space_check.h"
#include "surfaces/common/test/column_table_checks.h"

#include "surfaces/spherical/spherical_contact_analyzer.h"
#include "surfaces/spherical/spherical_discretizer.h"
#include "surfaces/spherical/spherical_generator.h"
#include "surfaces/spherical/test/test_parts.h"

namespace fitfeel::spherical {
namespace {

// The knuckle-bearing scenario's form and texture on the test bearing, with a ball whose size
// zone straddles the socket's (clearance for some seeds, interference for others).
void Prepare(SphericalContactAnalyzer* analyzer, std::uint64_t seed, TextureMode texture,
             double angular_reach = std::numeric_limits<double>::infinity()) {
  PartSpec ball = test::Ball();
  PartSpec socket = test::Socket();
  ball.size.lower_deviation = -10e-6;
  ball.size.upper_deviation = 10e-6;
  socket.size.upper_deviation = 10e-6;
  ball.form.tolerance[FormCharacteristic::kRoundness] = 6e-6;
  ball.form.tolerance[FormCharacteristic::kSphericity] = 9e-6;
  socket.form.tolerance[FormCharacteristic::kSphericity] = 9e-6;
  ball.texture = {0.0, 0.4e-6, 1.6e-6};
  socket.texture = {0.0, 0.4e-6, 1.6e-6};
  ModelSettings settings;
  settings.friction = 0.15;
  settings.contact_stiffness = 1e6;
  settings.texture = texture;
  settings.angular_reach = angular_reach;
  Rng rng(seed);
  const Resolution r{12, 72};
  const SkinModelShape ball_sms = SphericalVariationGenerator().Generate(
      ball, SphericalDiscretizer().Discretize(ball, r), texture, rng);
  const SkinModelShape socket_sms = SphericalVariationGenerator().Generate(
      socket, SphericalDiscretizer().Discretize(socket, r), texture, rng);
  analyzer->Prepare(ball, ball_sms, socket, socket_sms, settings);
}

MatingPose RandomPose(std::mt19937_64& rng, double angle) {
  std::uniform_real_distribution<double> direction(0.0, 2.0 * M_PI), reach(0.0, 30e-6);
  const double a = direction(rng);
  MatingPose pose;
  pose.angle = angle;
  pose.offset = reach(rng) * Eigen::Vector2d(std::cos(a), std::sin(a));
  return pose;
}

TEST(SphericalTable, EqualsTheScanAtTheRotationStepsWithinItsBound) {
  for (TextureMode texture : {TextureMode::kExpected, TextureMode::kSampled}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      SphericalContactAnalyzer analyzer;
      Prepare(&analyzer, seed, texture);
      std::mt19937_64 rng(100 + seed);
      for (int q = 0; q < analyzer.table().steps(); q += 7) {
        const double bound = test_support::TableVolumeBound(analyzer.table(), q);
        for (int trial = 0; trial < 10; ++trial) {
          const MatingPose pose = RandomPose(rng, q * analyzer.angle_step());
          const auto [table, scan] = test_support::ExpectTableWithin(
              analyzer, pose, bound, "seed " + std::to_string(seed) + " step " + std::to_string(q));
          EXPECT_EQ(table.engaged_area, scan.engaged_area);
        }
      }
    }
  }
}

TEST(SphericalTable, BetweenTheStepsStaysWithinTwoPercentOfTheScan) {
  double worst = 0.0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    SphericalContactAnalyzer analyzer;
    Prepare(&analyzer, seed, TextureMode::kExpected);
    std::mt19937_64 rng(200 + seed);
    std::uniform_real_distribution<double> angle(-7.0, 7.0);
    for (int trial = 0; trial < 400; ++trial) {
      const MatingPose pose = RandomPose(rng, angle(rng));
      const double error = test_support::TableRelativeError(analyzer, pose);
      worst = std::max(worst, error);
      EXPECT_LT(error, 0.02) << "seed " << seed << " angle " << pose.angle;
    }
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

// A run whose device swings the ball 15 degrees either way tabulates only that swing: within it
// every state is the whole table's bits; past it (no run of that device gets there) none.
TEST(SphericalTable, WithinTheDevicesSwingIsTheWholeTableBitForBit) {
  const double swing = 15.0 * M_PI / 180.0;
  SphericalContactAnalyzer whole, swung;
  Prepare(&whole, 3, TextureMode::kExpected);
  Prepare(&swung, 3, TextureMode::kExpected, swing);
  std::uniform_real_distribution<double> turn(-swing, swing);
  test_support::ExpectSameTicks(
      whole, swung, [&](std::mt19937_64& rng, const auto&) { return RandomPose(rng, turn(rng)); });
  // Half a turn away, pressed 40 um across, the swung table holds nothing.
  MatingPose far;
  far.angle = M_PI;
  far.offset = {40e-6, 0.0};
  ContactState a, b;
  whole.Evaluate(far, &a);
  swung.Evaluate(far, &b);
  EXPECT_GT(a.interference_volume, 0.0);
  EXPECT_EQ(b.interference_volume, 0.0);
}

TEST(SphericalTable, IsTheSameBitForBitOnOneOrTwoThreads) {
  test_support::ExpectSameTablesOnOneOrTwoThreads<SphericalContactAnalyzer>(
      [](SphericalContactAnalyzer* analyzer) { Prepare(analyzer, 3, TextureMode::kExpected); },
      [angle = std::uniform_real_distribution<double>(-7.0, 7.0)](
          std::mt19937_64& rng, const SphericalContactAnalyzer&) mutable {
        return RandomPose(rng, angle(rng));
      });
}

// The assembly space (what the viewer draws) is exactly the ball centre's contact-free offsets:
// with sharp contact, the scan touches nothing just inside the polygon and something just beyond
// each vertex; seeds whose ball interferes have an empty polygon and touch at the centre.
TEST(SphericalAssemblySpace, HoldsExactlyTheContactFreeOffsets) {
  int polygons = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    SphericalContactAnalyzer analyzer;
    Prepare(&analyzer, seed, TextureMode::kSampled);
    for (const double angle : {0.0, 0.3}) {
      MatingPose pose;
      pose.angle = angle;
      std::vector<Eigen::Vector2d> polygon;
      ASSERT_TRUE(analyzer.AssemblySpace(pose, &polygon));
      ContactState contact;
      if (polygon.empty()) {
        analyzer.scan().Evaluate(pose, &contact);
        EXPECT_GT(contact.interference_volume, 0.0) << "seed " << seed;
        continue;
      }
      ++polygons;
      test_support::ExpectPolygonIsTheContactFreeSpace(
          analyzer.scan(), pose, polygon,
          "seed " + std::to_string(seed) + " angle " + std::to_string(angle));
    }
  }
  EXPECT_GT(polygons, 0) << "every seed interfered: the polygon was never checked";
}

}  // namespace
}  // namespace fitfeel::spherical
