// The tabulated analyzer against the per-tick scan it replaces (the scan is the model; the table
// only changes how fast it is evaluated): at the rotation steps within the table's stated
// interpolation bound, between them within 2 % of the scan's interference volume, and bit for bit
// the same tables whatever the number of prepare threads.
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/testing/assembly_space_check.h"

#include "surfaces/spherical/spherical_contact_analyzer.h"
#include "surfaces/spherical/spherical_discretizer.h"
#include "surfaces/spherical/spherical_generator.h"
#include "surfaces/spherical/test/test_parts.h"

namespace fitfeel::spherical {
namespace {

// The knuckle-bearing scenario's form and texture on the test bearing, with a ball whose size
// zone straddles the socket's (clearance for some seeds, interference for others).
void Prepare(SphericalContactAnalyzer* analyzer, std::uint64_t seed, TextureMode texture) {
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
        double bound = 0.0;
        for (int j = 0; j < analyzer.table().columns(); ++j) {
          bound += analyzer.table().VolumeErrorBound(q, j);
        }
        for (int trial = 0; trial < 10; ++trial) {
          const MatingPose pose = RandomPose(rng, q * analyzer.angle_step());
          ContactState table, scan;
          analyzer.Evaluate(pose, &table);
          analyzer.scan().Evaluate(pose, &scan);
          EXPECT_EQ(table.engaged_area, scan.engaged_area);
          EXPECT_NEAR(table.interference_volume, scan.interference_volume,
                      bound + 1e-12 * scan.interference_volume)
              << "seed " << seed << " step " << q;
          EXPECT_LE((table.pressure_resultant - scan.pressure_resultant).norm(),
                    bound + 1e-12 * scan.interference_volume);
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
      ContactState table, scan;
      analyzer.Evaluate(pose, &table);
      analyzer.scan().Evaluate(pose, &scan);
      // Relative to a volume of at least 0.1 um over the band.
      const double scale = std::max(scan.interference_volume, 1e-7 * scan.engaged_area);
      const double error = std::abs(table.interference_volume - scan.interference_volume) / scale;
      worst = std::max(worst, error);
      EXPECT_LT(error, 0.02) << "seed " << seed << " angle " << pose.angle;
    }
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(SphericalTable, IsTheSameBitForBitOnOneOrTwoThreads) {
  SphericalContactAnalyzer one, two;
  setenv("FITFEEL_PREPARE_THREADS", "1", 1);
  Prepare(&one, 3, TextureMode::kExpected);
  setenv("FITFEEL_PREPARE_THREADS", "2", 1);
  Prepare(&two, 3, TextureMode::kExpected);
  unsetenv("FITFEEL_PREPARE_THREADS");
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> angle(-7.0, 7.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const MatingPose pose = RandomPose(rng, angle(rng));
    ContactState a, b;
    one.Evaluate(pose, &a);
    two.Evaluate(pose, &b);
    ASSERT_EQ(a.interference_volume, b.interference_volume);
    ASSERT_EQ(a.pressure_resultant, b.pressure_resultant);
    ASSERT_EQ(a.max_interference, b.max_interference);
  }
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
