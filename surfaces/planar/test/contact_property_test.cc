// Properties of the contact analysis on generated skin model shapes, over many seeds: the tabulated
// assembly interval is the brute-force one, the balance position carries no net force, and the
// interference map sums to the tabulated volume.
#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "surfaces/planar/planar_contact_analyzer.h"
#include "surfaces/planar/planar_generator.h"
#include "surfaces/planar/planar_discretizer.h"
#include "surfaces/planar/test/test_support.h"

namespace fitfeel::planar {
namespace {

using testing::MakePart;

TEST(PlanarContactPropertyTest, FullEngagementMatchesBruteForceOverSeeds) {
  // Equal lengths and row pitches: at depth = length every key row faces the slot row of the
  // same index, so the brute force is a plain loop over cells.
  PartSpec key = MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 40e-3, 2.6e-3);
  PartSpec slot = MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 40e-3, 2.6e-3);
  key.form.tolerance[FormCharacteristic::kFlatness] = 12e-6;
  slot.form.tolerance[FormCharacteristic::kFlatness] = 12e-6;
  const SurfaceGrid gk = PlanarDiscretizer().Discretize(key, Resolution{});
  const SurfaceGrid gs = PlanarDiscretizer().Discretize(slot, Resolution{});
  const FaceLayout layout = LayoutOf(gk);
  int interfering = 0;
  for (int seed = 1; seed <= 60; ++seed) {
    Rng rng(seed);
    const SkinModelShape k =
        PlanarVariationGenerator().Generate(key, gk, TextureMode::kExpected, rng);
    const SkinModelShape s =
        PlanarVariationGenerator().Generate(slot, gs, TextureMode::kExpected, rng);
    PlanarContactAnalyzer a;
    a.Prepare(key, k, slot, s, ModelSettings{});
    double hi = std::numeric_limits<double>::infinity(), lo = -hi;
    for (int c = 0; c < gk.size(); ++c) {
      const double gap = s.variation[c] - k.variation[c];
      if (layout.face_of(c % gk.columns) == 0) hi = std::min(hi, gap);
      if (layout.face_of(c % gk.columns) == 1) lo = std::max(lo, -gap);
    }
    const double depth = 40e-3;
    const int step = static_cast<int>(std::lround(depth / a.depth_step()));
    ASSERT_NEAR(step * a.depth_step(), depth, 1e-12);
    EXPECT_DOUBLE_EQ(a.upper(step, 0), hi) << seed;
    EXPECT_DOUBLE_EQ(a.lower(step, 0), lo) << seed;
    MatingPose pose;
    pose.depth = depth;
    ContactState state;
    a.Evaluate(pose, &state);
    EXPECT_EQ(state.interference, lo > hi) << seed;
    if (lo > hi) {
      ++interfering;
      const double x = a.balance(step, 0);
      double net = 0.0, scale = 0.0;
      for (int c = 0; c < gk.size(); ++c) {
        const double gap = s.variation[c] - k.variation[c];
        const double along = layout.face_of(c % gk.columns) == 0 ? x : -x;
        const double f = gk.area[c] * std::max(0.0, along - gap);
        net += layout.face_of(c % gk.columns) == 0 ? f : -f;
        scale += f;
      }
      EXPECT_LT(std::abs(net), 1e-9 * scale) << seed;
      Eigen::VectorXd map;
      pose.offset = {x, 0.0};
      a.InterferenceMap(pose, &map);
      EXPECT_NEAR(map.dot(gk.area), state.interference_volume, 1e-9 * scale) << seed;
    } else {
      // Only the neighbouring step, at a weight of rounding size, may add anything.
      EXPECT_LT(state.interference_volume, 1e-20) << seed;
    }
  }
  // h9 in JS9 interferes in a good share of draws; the property must have been exercised.
  EXPECT_GT(interfering, 5);
}

}  // namespace
}  // namespace fitfeel::planar
