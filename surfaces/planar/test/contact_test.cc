// Planar contact analysis on synthetic skin model shapes with known tolerance spaces.
#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "framework/model/texture_contact.h"
#include "surfaces/planar/planar_contact_analyzer.h"
#include "surfaces/planar/planar_discretizer.h"
#include "surfaces/planar/test/test_support.h"

namespace fitfeel::planar {
namespace {

using testing::MakePart;

// A skin model shape whose V is v(face) on every cell of that face.
SkinModelShape Shape(const PartSpec& part, const Resolution& res,
                     const std::function<double(int face)>& v) {
  SkinModelShape sms;
  sms.grid = PlanarDiscretizer().Discretize(part, res);
  const FaceLayout layout = LayoutOf(sms.grid);
  sms.variation.resize(sms.grid.size());
  for (int c = 0; c < sms.grid.size(); ++c) {
    sms.variation[c] = v(layout.face_of(c % sms.grid.columns));
  }
  return sms;
}

struct Pair {
  PartSpec key = MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 40e-3, 3e-3);
  PartSpec slot = MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 60e-3, 3e-3);
};

TEST(PlanarContactTest, UniformClearanceGivesASymmetricIntervalAndASpringBeyondIt) {
  Pair p;
  const double c1 = 3e-6, c2 = 2e-6;
  const auto key = Shape(p.key, Resolution{16, 6}, [&](int) { return -c1; });
  const auto slot = Shape(p.slot, Resolution{24, 6}, [&](int) { return c2; });
  PlanarContactAnalyzer a;
  a.Prepare(p.key, key, p.slot, slot, ModelSettings{});
  ContactState s;
  MatingPose pose;
  pose.depth = 45e-3;  // fully inside
  a.Evaluate(pose, &s);
  EXPECT_TRUE(s.engaged);
  EXPECT_FALSE(s.interference);
  EXPECT_NEAR(s.engaged_length, 40e-3, 1e-12);
  EXPECT_NEAR(s.engaged_area, 2 * 3e-3 * 40e-3, 1e-14);
  EXPECT_EQ(s.penetration, 0.0);
  EXPECT_EQ(s.interference_volume, 0.0);
  pose.offset = {c1 + c2 + 4e-6, 0.0};
  a.Evaluate(pose, &s);
  EXPECT_NEAR(s.penetration, 4e-6, 1e-15);
  EXPECT_NEAR(std::cos(s.offset_angle), 1.0, 1e-12);
  pose.offset = {-(c1 + c2) - 1e-6, 7e-3};  // z is free for a key
  a.Evaluate(pose, &s);
  EXPECT_NEAR(s.penetration, 1e-6, 1e-15);
  EXPECT_NEAR(std::cos(s.offset_angle), -1.0, 1e-12);
}

TEST(PlanarContactTest, HalfEngagedKeyHasHalfTheLengthAndAreaAndNothingBeforeTheEntrance) {
  Pair p;
  const auto key = Shape(p.key, Resolution{16, 6}, [](int) { return 0.0; });
  const auto slot = Shape(p.slot, Resolution{24, 6}, [](int) { return 1e-6; });
  PlanarContactAnalyzer a;
  a.Prepare(p.key, key, p.slot, slot, ModelSettings{});
  ContactState s;
  MatingPose pose;
  pose.depth = 20e-3;
  a.Evaluate(pose, &s);
  EXPECT_NEAR(s.engaged_length, 20e-3, 1e-15);
  EXPECT_NEAR(s.engaged_area, 2 * 3e-3 * 20e-3, 1e-15);
  pose.depth = 10.3e-3;  // between table steps: linear in depth
  a.Evaluate(pose, &s);
  EXPECT_NEAR(s.engaged_length, 10.3e-3, 1e-15);
  pose.depth = -1e-3;
  pose.offset = {1e-3, 0.0};
  a.Evaluate(pose, &s);
  EXPECT_FALSE(s.engaged);
  EXPECT_EQ(s.penetration, 0.0);
}

TEST(PlanarContactTest, UniformInterferenceCentresTheKeyAndSumsBothFlanks) {
  Pair p;
  const double delta = 1e-6;
  const auto key = Shape(p.key, Resolution{16, 6}, [&](int) { return delta; });
  const auto slot = Shape(p.slot, Resolution{24, 6}, [](int) { return 0.0; });
  PlanarContactAnalyzer a;
  a.Prepare(p.key, key, p.slot, slot, ModelSettings{});
  ContactState s;
  MatingPose pose;
  pose.depth = 50e-3;
  a.Evaluate(pose, &s);
  EXPECT_TRUE(s.interference);
  EXPECT_NEAR(s.interference_volume, 2 * delta * 3e-3 * 40e-3, 1e-20);
  EXPECT_NEAR(s.max_interference, delta, 1e-18);
  EXPECT_NEAR(s.pressure_resultant.norm(), 0.0, 1e-20);
  EXPECT_NEAR(s.penetration, 0.0, 1e-18);
  pose.offset = {2e-6, 0.0};  // pushed off the balance position: the spring pulls it back
  a.Evaluate(pose, &s);
  EXPECT_NEAR(s.penetration, 2e-6, 1e-17);
}

TEST(PlanarContactTest, AsymmetricInterferenceBalancesTheFaces) {
  // +x flank interferes by 2 delta, -x flank touches: the key moves to x = -delta, where each
  // flank carries delta.
  Pair p;
  const double delta = 1e-6;
  const auto key = Shape(p.key, Resolution{16, 6}, [&](int f) { return f == 0 ? 2 * delta : 0.0; });
  const auto slot = Shape(p.slot, Resolution{24, 6}, [](int) { return 0.0; });
  PlanarContactAnalyzer a;
  a.Prepare(p.key, key, p.slot, slot, ModelSettings{});
  const int k = a.depth_steps() / 2;
  EXPECT_NEAR(a.balance(k, 0), -delta, 1e-17);
  ContactState s;
  MatingPose pose;
  pose.depth = 50e-3;
  a.Evaluate(pose, &s);
  EXPECT_NEAR(s.interference_volume, 2 * delta * 3e-3 * 40e-3, 1e-20);
  Eigen::VectorXd map;
  a.InterferenceMap(pose, &map);
  EXPECT_NEAR(map.dot(key.grid.area), s.interference_volume, 1e-20);
  EXPECT_NEAR(map.maxCoeff(), delta, 1e-17);
}

TEST(PlanarContactTest, SquareShaftHasARectangleAndInterferesPerAxis) {
  PartSpec shaft = MakePart("shaft", Role::kInner, 20e-3, -21e-6, 0.0, 30e-3, 18e-3, 4);
  PartSpec hole = MakePart("hole", Role::kOuter, 20e-3, 0.0, 21e-6, 30e-3, 18e-3, 4);
  // x faces clear by 3 um each side; z faces interfere by 1 um each side.
  const auto s_in = Shape(shaft, Resolution{12, 8}, [](int f) { return f < 2 ? -3e-6 : 1e-6; });
  const auto s_out = Shape(hole, Resolution{12, 8}, [](int) { return 0.0; });
  PlanarContactAnalyzer a;
  a.Prepare(shaft, s_in, hole, s_out, ModelSettings{});
  const int k = a.depth_steps() - 1 - a.depth_steps() / 2;  // about full engagement
  EXPECT_NEAR(a.lower(k, 0), -3e-6, 1e-18);
  EXPECT_NEAR(a.upper(k, 0), 3e-6, 1e-18);
  EXPECT_GT(a.lower(k, 1), a.upper(k, 1));
  ContactState s;
  MatingPose pose;
  pose.depth = 30e-3;
  pose.offset = {5e-6, 0.5e-6};
  a.Evaluate(pose, &s);
  EXPECT_TRUE(s.interference);
  EXPECT_NEAR(s.interference_volume, 2 * 1e-6 * 18e-3 * 30e-3, 1e-20);
  EXPECT_NEAR(s.penetration, std::hypot(2e-6, 0.5e-6), 1e-17);
}

// What the viewer draws: the rectangle of free offsets, empty where an axis interferes.
TEST(PlanarContactTest, AssemblySpaceIsTheRectangleOfFreeOffsets) {
  PartSpec shaft = MakePart("shaft", Role::kInner, 20e-3, -21e-6, 0.0, 30e-3, 18e-3, 4);
  PartSpec hole = MakePart("hole", Role::kOuter, 20e-3, 0.0, 21e-6, 30e-3, 18e-3, 4);
  const auto s_out = Shape(hole, Resolution{12, 8}, [](int) { return 0.0; });
  MatingPose pose;
  pose.depth = 30e-3;
  std::vector<Eigen::Vector2d> polygon;
  {
    // x faces clear by 3 um each side, z faces by 2 um.
    const auto s_in = Shape(shaft, Resolution{12, 8}, [](int f) { return f < 2 ? -3e-6 : -2e-6; });
    PlanarContactAnalyzer a;
    a.Prepare(shaft, s_in, hole, s_out, ModelSettings{});
    ASSERT_TRUE(a.AssemblySpace(pose, &polygon));
    ASSERT_EQ(polygon.size(), 4u);
    const Eigen::Vector2d corner[] = {{-3e-6, -2e-6}, {3e-6, -2e-6}, {3e-6, 2e-6}, {-3e-6, 2e-6}};
    for (int i = 0; i < 4; ++i) EXPECT_LT((polygon[i] - corner[i]).norm(), 1e-18) << i;
    pose.depth = -1e-3;
    ASSERT_TRUE(a.AssemblySpace(pose, &polygon));
    EXPECT_TRUE(polygon.empty()) << "not engaged yet";
  }
  {
    // z faces interfere by 1 um: no free offset at all.
    const auto s_in = Shape(shaft, Resolution{12, 8}, [](int f) { return f < 2 ? -3e-6 : 1e-6; });
    PlanarContactAnalyzer a;
    a.Prepare(shaft, s_in, hole, s_out, ModelSettings{});
    pose.depth = 30e-3;
    ASSERT_TRUE(a.AssemblySpace(pose, &polygon));
    EXPECT_TRUE(polygon.empty());
  }
  {
    // A key: its z is free, drawn as high as the x interval is wide.
    Pair p;
    const auto key = Shape(p.key, Resolution{10, 4}, [](int) { return -2e-6; });
    const auto slot = Shape(p.slot, Resolution{10, 4}, [](int) { return 1e-6; });
    PlanarContactAnalyzer a;
    a.Prepare(p.key, key, p.slot, slot, ModelSettings{});
    pose.depth = 40e-3;
    ASSERT_TRUE(a.AssemblySpace(pose, &polygon));
    ASSERT_EQ(polygon.size(), 4u);
    EXPECT_NEAR(polygon[0].x(), -3e-6, 1e-18);
    EXPECT_NEAR(polygon[2].x(), 3e-6, 1e-18);
    EXPECT_NEAR(polygon[2].y() - polygon[0].y(), 6e-6, 1e-18);
  }
}

TEST(PlanarContactTest, RefusesMismatchedStrips) {
  Pair p;
  const auto key = Shape(p.key, Resolution{16, 6}, [](int) { return 0.0; });
  const auto slot = Shape(p.slot, Resolution{24, 4}, [](int) { return 0.0; });
  PlanarContactAnalyzer a;
  EXPECT_THROW(a.Prepare(p.key, key, p.slot, slot, ModelSettings{}), UserError);
}

TEST(PlanarContactTest, ExpectedTextureInterferenceInClearanceIsTheTruncatedGaussianClosedForm) {
  // Uniform clearance g per flank, both parts textured: at the middle of the interval each flank
  // has gap g, and the expected interference per unit area is E[(X - g)+] of the equivalent
  // texture (docs/oracles.md closed form).
  Pair p;
  p.key.texture = {3.2e-6, 0.4e-6, 1.6e-6};
  p.slot.texture = {3.2e-6, 0.4e-6, 1.6e-6};
  const double g = 1.5e-6;
  const auto key = Shape(p.key, Resolution{16, 6}, [](int) { return 0.0; });
  const auto slot = Shape(p.slot, Resolution{24, 6}, [&](int) { return g; });
  PlanarContactAnalyzer a;
  ModelSettings expected;
  a.Prepare(p.key, key, p.slot, slot, expected);
  ContactState s;
  MatingPose pose;
  pose.depth = 45e-3;
  a.Evaluate(pose, &s);
  const double per_area = ExpectedInterference(EquivalentTexture(p.key.texture, p.slot.texture), g);
  EXPECT_GT(per_area, 0.0);
  EXPECT_FALSE(s.interference);
  EXPECT_NEAR(s.interference_volume, 2 * 3e-3 * 40e-3 * per_area, 1e-6 * s.interference_volume);
  // Sampled texture lives in V: the analyzer then treats the contact as sharp.
  ModelSettings sampled;
  sampled.texture = TextureMode::kSampled;
  a.Prepare(p.key, key, p.slot, slot, sampled);
  a.Evaluate(pose, &s);
  EXPECT_EQ(s.interference_volume, 0.0);
}

}  // namespace
}  // namespace fitfeel::planar
