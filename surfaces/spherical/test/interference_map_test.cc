// The analyzer's interference map is over the ball's (inner part's) cells, as the ContactAnalyzer
// contract says: sized as the ball's grid, zero outside the socket's band, and, where the ball's
// rows and columns fall on the socket's, the same interference the tick sums.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/spherical/spherical_contact_analyzer.h"
#include "surfaces/spherical/spherical_discretizer.h"
#include "surfaces/spherical/spherical_generator.h"
#include "surfaces/spherical/test/test_parts.h"

namespace fitfeel::spherical {
namespace {

constexpr int kColumns = 72;

struct Prepared {
  SphericalContactAnalyzer analyzer;
  SkinModelShape ball;
  SkinModelShape socket;
};

// Ball band 14 mm in 14 rows, socket band 10 mm in 10 rows: 1 mm pitch on both, so ball rows 2 to
// 11 are centred on socket rows 0 to 9. The ball is 1 um (radially) too big.
void Prepare(Prepared* p, std::uint64_t seed) {
  PartSpec ball = test::Ball();
  PartSpec socket = test::Socket();
  ball.size.lower_deviation = 2e-6 - 3e-6;
  ball.size.upper_deviation = 2e-6 + 3e-6;
  socket.size.upper_deviation = 4e-6;
  Rng rng(seed);
  const SphericalDiscretizer discretizer;
  const SphericalVariationGenerator generator;
  p->ball = generator.Generate(ball, discretizer.Discretize(ball, Resolution{14, kColumns}),
                               TextureMode::kSampled, rng);
  p->socket = generator.Generate(socket, discretizer.Discretize(socket, Resolution{10, kColumns}),
                                 TextureMode::kSampled, rng);
  // Uneven skins (the generator gives none without form specifications): every cell's variation
  // moved by up to +-2 um, so that the cells' pairing matters.
  std::uniform_real_distribution<double> bump(-2e-6, 2e-6);
  for (auto* sms : {&p->ball, &p->socket}) {
    for (Eigen::Index k = 0; k < sms->variation.size(); ++k) sms->variation(k) += bump(rng);
  }
  ModelSettings settings;
  settings.texture = TextureMode::kSampled;
  p->analyzer.Prepare(ball, p->ball, socket, p->socket, settings);
}

TEST(SphericalInterferenceMap, CoversTheBallsGridAndIsZeroOutsideTheSocketsBand) {
  Prepared p;
  Prepare(&p, 7);
  MatingPose pose;
  pose.offset = Eigen::Vector2d(3e-6, -1e-6);
  Eigen::VectorXd delta;
  p.analyzer.InterferenceMap(pose, &delta);
  ASSERT_EQ(delta.size(), p.ball.grid.size());
  for (int r : {0, 1, 12, 13}) {
    for (int c = 0; c < kColumns; ++c) EXPECT_EQ(delta(p.ball.grid.index(r, c)), 0.0);
  }
  EXPECT_GT(delta.maxCoeff(), 0.0);
  EXPECT_GE(delta.minCoeff(), 0.0);
}

// For rotations by whole column pitches the ball's cells sit exactly on the socket's, so the map
// over the ball's cells holds the very interferences the tick sums over the socket's.
TEST(SphericalInterferenceMap, AgreesWithTheTickOnAlignedCellsForManySeeds) {
  const double pitch = 2.0 * M_PI / kColumns;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Prepared p;
    Prepare(&p, seed);
    Rng pose_rng(1000 + seed);
    std::uniform_real_distribution<double> offset(-4e-6, 4e-6);
    for (int turn : {0, 1, 5, -7, 40}) {
      MatingPose pose;
      pose.angle = turn * pitch;
      pose.offset = Eigen::Vector2d(offset(pose_rng), offset(pose_rng));
      // The map is the scan's; the tabulated tick is tested against the scan in table_test.cc.
      ContactState state;
      p.analyzer.scan().Evaluate(pose, &state);
      Eigen::VectorXd delta;
      p.analyzer.InterferenceMap(pose, &delta);
      const double area = p.ball.grid.area(0);  // equal to the socket's: same pitch and radius
      ASSERT_NEAR(area, p.socket.grid.area(0), 1e-15);
      EXPECT_NEAR(delta.sum() * area, state.interference_volume,
                  1e-9 * state.interference_volume + 1e-24)
          << "seed " << seed << " turn " << turn;
      EXPECT_NEAR(delta.maxCoeff(), state.max_interference, 1e-15)
          << "seed " << seed << " turn " << turn;
      // The pressure resultant direction: sum delta * n over the ball's turned normals.
      Eigen::Vector2d resultant = Eigen::Vector2d::Zero();
      for (int k = 0; k < delta.size(); ++k) {
        const double beta = p.ball.grid.column_angle(k % kColumns) + pose.angle;
        const double rho = std::hypot(p.ball.grid.normal(0, k), p.ball.grid.normal(2, k));
        resultant += delta(k) * area * rho * Eigen::Vector2d(std::cos(beta), std::sin(beta));
      }
      EXPECT_NEAR((resultant - state.pressure_resultant).norm(), 0.0,
                  1e-9 * state.pressure_resultant.norm() + 1e-24)
          << "seed " << seed << " turn " << turn;
    }
  }
}

TEST(SphericalInterferenceMap, RefusesANonFinitePose) {
  Prepared p;
  Prepare(&p, 3);
  MatingPose pose;
  pose.angle = std::nan("");
  Eigen::VectorXd delta;
  EXPECT_THROW(p.analyzer.InterferenceMap(pose, &delta), UserError);
}

}  // namespace
}  // namespace fitfeel::spherical
