#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "framework/core/error.h"
#include "framework/model/texture_contact.h"
#include "surfaces/cylindrical/cylindrical_contact_analyzer.h"
#include "surfaces/cylindrical/cylindrical_surface.h"
#include "surfaces/cylindrical/test/contact_test_support.h"

// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace fitfeel::cylindrical {
namespace {

using namespace testing;

struct SyntheticPair {
  PartSpec shaft = MakeShaft(0.020, 0.040);
  PartSpec bushing = MakeBushing(0.020, 0.020, 0.030);
  SurfaceGrid shaft_grid = MakeGrid(40, 36, 0.020, 0.040);
  SurfaceGrid bushing_grid = MakeGrid(20, 36, 0.020, 0.020);
};

ContactState ContactAt(const ContactAnalyzer& a, double depth, Eigen::Vector2d offset = {0, 0}) {
  ContactState s;
  MatingPose pose;
  pose.depth = depth;
  pose.offset = offset;
  a.Evaluate(pose, &s);
  return s;
}

TEST(CylinderContact, UniformClearanceGivesRegularAssemblySpace) {
  SyntheticPair p;
  const double c = 6 * kUm;  // radial clearance: bushing +6 um, shaft 0
  CylinderContactAnalyzer a;
  a.Prepare(p.shaft, MakeSms(p.shaft_grid, [](int, int) { return 0.0; }), p.bushing,
            MakeSms(p.bushing_grid, [&](int, int) { return c; }),
            Settings(0.15, 0.0, TextureMode::kSampled));
  const int n = 36;
  EXPECT_LE(a.max_polygon_vertices(), n + 4);
  for (double depth : {0.5e-3, 10e-3, 25e-3, 55e-3}) {
    // Along a column direction the extent is the inscribed radius c; along a vertex c/cos(pi/n).
    for (int j : {0, 5, 17}) {
      const double b = 2 * kPi * j / n;
      const Eigen::Vector2d u(std::cos(b), std::sin(b));
      ContactState s = ContactAt(a, depth, 1 * kUm * u);
      EXPECT_TRUE(s.engaged);
      EXPECT_FALSE(s.interference);
      EXPECT_NEAR(s.assembly_extent, c, 1e-15) << depth;
      EXPECT_EQ(s.penetration, 0.0);
      s = ContactAt(a, depth, (c + 2 * kUm) * u);
      // Within the first and last depth step the anchor blends with the free (unengaged) state:
      // the radial spring ramps in over one step instead of switching on.
      const double ramp = depth < a.depth_step() ? depth / a.depth_step()
                          : depth > a.max_depth() - a.depth_step()
                              ? (a.max_depth() - depth) / a.depth_step()
                              : 1.0;
      EXPECT_NEAR(s.penetration, 2 * kUm * ramp, 1e-15) << depth;
      EXPECT_NEAR((s.penetration_direction - u).norm(), 0.0, 1e-9);
      const double bv = b + kPi / n;
      const Eigen::Vector2d uv(std::cos(bv), std::sin(bv));
      s = ContactAt(a, depth, 0.5 * kUm * uv);
      EXPECT_NEAR(s.assembly_extent, c / std::cos(kPi / n), 1e-15);
      EXPECT_NEAR(s.offset_angle, std::remainder(bv, 2 * kPi), 1e-12);
    }
    EXPECT_EQ(ContactAt(a, depth).interference_volume, 0.0);
  }
  // Pressed 1 um into the wall at column 0: the map shows the contact line there only.
  MatingPose pose;
  pose.depth = 30e-3;
  pose.offset = {c + 1 * kUm, 0.0};
  Eigen::VectorXd map;
  a.InterferenceMap(pose, &map);
  EXPECT_NEAR(map[p.shaft_grid.index(20, 0)], 1 * kUm, 1e-15);
  EXPECT_NEAR(map[p.shaft_grid.index(20, 1)], std::max(0.0, (c + kUm) * std::cos(2 * kPi / n) - c),
              1e-15);
  EXPECT_EQ(map[p.shaft_grid.index(20, n / 2)], 0.0);
  EXPECT_EQ(map[p.shaft_grid.index(5, 0)], 0.0);  // not yet in the bushing
  // Engagement follows the alignment: depth 0 = leading end at the entrance.
  EXPECT_FALSE(ContactAt(a, -1e-3).engaged);
  EXPECT_FALSE(ContactAt(a, 0.0).engaged);
  EXPECT_NEAR(ContactAt(a, 5e-3).engaged_length, 5e-3, 1e-12);
  EXPECT_NEAR(ContactAt(a, 30e-3).engaged_length, 20e-3, 1e-12);
  EXPECT_NEAR(ContactAt(a, 50e-3).engaged_length, 10e-3, 1e-12);
  EXPECT_NEAR(ContactAt(a, 30e-3).engaged_area, kPi * 0.020 * 0.020, 1e-12);
  EXPECT_FALSE(ContactAt(a, 60e-3).engaged);
  EXPECT_FALSE(ContactAt(a, std::nan("")).engaged);
  EXPECT_FALSE(ContactAt(a, 30e-3, {std::nan(""), 0.0}).engaged);
  EXPECT_FALSE(ContactAt(a, std::numeric_limits<double>::infinity()).engaged);
}

TEST(CylinderContact, OffsetBoreShiftsTheAssemblySpace) {
  SyntheticPair p;
  const double c = 8 * kUm;
  const Eigen::Vector2d o(3 * kUm, 0.2 * kUm);  // bore axis offset
  const int n = 36;
  CylinderContactAnalyzer a;
  a.Prepare(p.shaft, MakeSms(p.shaft_grid, [](int, int) { return 0.0; }), p.bushing,
            MakeSms(p.bushing_grid,
                    [&](int, int j) {
                      const double b = 2 * kPi * j / n;
                      return c + o.x() * std::cos(b) + o.y() * std::sin(b);
                    }),
            Settings(0.15, 0.0, TextureMode::kSampled));
  const int k = static_cast<int>(std::round(30e-3 / a.depth_step()));
  EXPECT_NEAR((a.anchor(k) - o).norm(), 0.0, 1e-15);
  // Leaving the shifted polygon through a face.
  const Eigen::Vector2d u(std::cos(2 * kPi * 9 / n), std::sin(2 * kPi * 9 / n));
  const ContactState s = ContactAt(a, 30e-3, o + (c + 1.5 * kUm) * u);
  EXPECT_NEAR(s.penetration, 1.5 * kUm, 1e-14);
  EXPECT_NEAR((s.penetration_direction - u).norm(), 0.0, 1e-8);
  // S_A along +x from the fixed axis: the face x = c + o.x.
  EXPECT_NEAR(ContactAt(a, 30e-3, {1e-7, 0}).assembly_extent, c + o.x(), 1e-14);
}

TEST(CylinderContact, EllipticalBoreExtents) {
  SyntheticPair p;
  const int n = 360;
  p.shaft_grid = MakeGrid(8, n, 0.020, 0.040);
  p.bushing_grid = MakeGrid(4, n, 0.020, 0.020);
  const double c = 10 * kUm, e = 2 * kUm;  // V = c + e cos 2 beta: support function convex (c > 3e)
  CylinderContactAnalyzer a;
  a.Prepare(p.shaft, MakeSms(p.shaft_grid, [](int, int) { return 0.0; }), p.bushing,
            MakeSms(p.bushing_grid, [&](int, int j) { return c + e * std::cos(4 * kPi * j / n); }),
            Settings(0.15, 0.0, TextureMode::kSampled));
  EXPECT_NEAR(ContactAt(a, 30e-3, {1e-7, 0}).assembly_extent, c + e, 1e-15);
  EXPECT_NEAR(ContactAt(a, 30e-3, {0, 1e-7}).assembly_extent, c - e, 1e-15);
  EXPECT_NEAR(ContactAt(a, 30e-3, {-1e-7, 0}).assembly_extent, c + e, 1e-15);
}

// Different row pitches: the per-angle minimum must equal a brute-force minimum over every
// (shaft row, bushing row) pair whose axial intervals overlap at that depth.
TEST(CylinderContact, DifferentRowPitchesMapThroughAxialPosition) {
  for (int seed = 0; seed < 20; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> rows(3, 30);
    const int ms = rows(rng), mb = rows(rng), n = 6;
    const double ls = 0.030 + 0.001 * (seed % 7), lb = 0.017 + 0.0013 * (seed % 5);
    PartSpec shaft = MakeShaft(0.020, ls), bushing = MakeBushing(0.020, lb, 0.030);
    std::uniform_real_distribution<double> vs(-3e-6, 3e-6), vb(4e-6, 12e-6);
    std::vector<double> row_s(ms), row_b(mb);
    for (double& v : row_s) v = vs(rng);
    for (double& v : row_b) v = vb(rng);
    ModelSettings st = Settings(0.15, 0.0, TextureMode::kSampled);
    st.depth_step = 0.25e-3;
    CylinderContactAnalyzer b;
    b.Prepare(shaft, MakeSms(MakeGrid(ms, n, 0.020, ls), [&](int i, int) { return row_s[i]; }),
              bushing, MakeSms(MakeGrid(mb, n, 0.020, lb), [&](int k, int) { return row_b[k]; }),
              st);
    for (int step = 1; step < b.depth_steps() - 1; step += 3) {
      const double depth = step * st.depth_step;
      double h = 1e9;
      for (int i = 0; i < ms; ++i) {
        // Shaft row i in bushing coordinates at this depth.
        const double s0 = depth - ls + i * ls / ms, s1 = depth - ls + (i + 1) * ls / ms;
        for (int k = 0; k < mb; ++k) {
          const double b0 = k * lb / mb, b1 = (k + 1) * lb / mb;
          if (std::min(s1, b1) - std::max(s0, b0) > 1e-12) h = std::min(h, row_b[k] - row_s[i]);
        }
      }
      const ContactState s = ContactAt(b, depth, {1e-9, 0});
      ASSERT_TRUE(s.engaged);
      EXPECT_NEAR(s.assembly_extent, h, 1e-15) << "seed " << seed << " depth " << depth;
    }
  }
}

TEST(CylinderContact, UniformInterferenceCentresTheAxis) {
  SyntheticPair p;
  const double d = 1 * kUm;
  const Eigen::Vector2d o(0.3 * kUm, 0.2 * kUm);  // shaft's own axis offset (form)
  const int n = 36;
  CylinderContactAnalyzer a;
  a.Prepare(p.shaft,
            MakeSms(p.shaft_grid,
                    [&](int, int j) {
                      const double b = 2 * kPi * j / n;
                      return d + o.x() * std::cos(b) + o.y() * std::sin(b);
                    }),
            p.bushing, MakeSms(p.bushing_grid, [](int, int) { return 0.0; }),
            Settings(0.15, 0.0, TextureMode::kSampled));
  const ContactState s = ContactAt(a, 30e-3, {0, 0});
  EXPECT_TRUE(s.interference);
  // Energy minimum: the shaft's real axis sits on the bore's, i.e. the nominal axis at -o, and the
  // interference is d everywhere.
  const int k = static_cast<int>(std::round(30e-3 / a.depth_step()));
  EXPECT_NEAR((a.anchor(k) + o).norm(), 0.0, 1e-14);
  EXPECT_NEAR(s.interference_volume, d * kPi * 0.020 * 0.020, 1e-9 * d * kPi * 0.020 * 0.020);
  EXPECT_NEAR(s.max_interference, d, 1e-14);
  EXPECT_LT(s.pressure_resultant.norm(), 1e-6 * s.interference_volume);
  EXPECT_NEAR(s.penetration, o.norm(), 1e-14);  // the axis at 0 is o away from -o
  Eigen::VectorXd map;
  MatingPose pose;
  pose.depth = 30e-3;
  a.InterferenceMap(pose, &map);
  ASSERT_EQ(map.size(), p.shaft_grid.size());
  // Shaft rows 0..9 (trailing 10 mm) are behind the bushing at 30 mm; 10..29 inside; 30..39 out.
  EXPECT_EQ(map[p.shaft_grid.index(5, 3)], 0.0);
  EXPECT_NEAR(map[p.shaft_grid.index(20, 3)], d, 1e-14);
  EXPECT_EQ(map[p.shaft_grid.index(35, 3)], 0.0);
}

TEST(CylinderContact, ExpectedTextureInterference) {
  SyntheticPair p;
  const TextureSpec t{3.2 * kUm, 0.4 * kUm, 1.6 * kUm};
  p.shaft.texture = t;
  p.bushing.texture = t;
  const TruncatedGaussian x = EquivalentTexture(t, t);
  const double area = kPi * 0.020 * 0.020;
  for (double c : {-6.0 * kUm, -2 * kUm, 0.0, 1.5 * kUm, 3.0 * kUm, 6 * kUm}) {
    CylinderContactAnalyzer a;
    a.Prepare(p.shaft, MakeSms(p.shaft_grid, [](int, int) { return 0.0; }), p.bushing,
              MakeSms(p.bushing_grid, [&](int, int) { return c; }), Settings());
    const ContactState s = ContactAt(a, 30e-3);
    // Uniform gap c at the centred axis: volume = area * E[(X - c)+]; deep interference = -c.
    EXPECT_NEAR(s.interference_volume, area * ExpectedInterference(x, c), 1e-6 * x.sigma * area)
        << c;
    EXPECT_EQ(s.interference, c < 0.0);
  }
}

TEST(CylinderContact, RefusesMismatchedGrids) {
  SyntheticPair p;
  CylinderContactAnalyzer a;
  EXPECT_THROW(
      a.Prepare(p.shaft, MakeSms(MakeGrid(4, 36, 0.02, 0.04), [](int, int) { return 0.0; }),
                p.bushing, MakeSms(MakeGrid(4, 24, 0.02, 0.02), [](int, int) { return 0.0; }),
                Settings()),
      UserError);
  EXPECT_THROW(
      a.Prepare(p.bushing, MakeSms(MakeGrid(4, 36, 0.02, 0.04), [](int, int) { return 0.0; }),
                p.shaft, MakeSms(MakeGrid(4, 36, 0.02, 0.02), [](int, int) { return 0.0; }),
                Settings()),
      UserError);
  EXPECT_THROW(
      a.Prepare(p.shaft, MakeSms(MakeGrid(4, 2, 0.02, 0.04), [](int, int) { return 0.0; }),
                p.bushing, MakeSms(MakeGrid(4, 2, 0.02, 0.02), [](int, int) { return 0.0; }),
                Settings()),
      UserError);
  ModelSettings tiny = Settings();
  tiny.depth_step = 1e-12;
  EXPECT_THROW(
      a.Prepare(p.shaft, MakeSms(MakeGrid(4, 6, 0.02, 0.04), [](int, int) { return 0.0; }),
                p.bushing, MakeSms(MakeGrid(4, 6, 0.02, 0.02), [](int, int) { return 0.0; }), tiny),
      UserError);
}

TEST(CylinderContact, SurfaceOffersEveryLaw) {
  const CylindricalSurface surface;
  EXPECT_EQ(surface.law_names(), (std::vector<std::string>{"gps", "elastic", "ve1"}));
  EXPECT_NE(surface.MakeLaw("gps"), nullptr);
  EXPECT_NE(surface.MakeLaw("elastic"), nullptr);
  EXPECT_NE(surface.MakeLaw("ve1"), nullptr);
  EXPECT_NE(surface.MakeContactAnalyzer(), nullptr);
  EXPECT_THROW(surface.MakeLaw("vE2"), UserError);
}

}  // namespace
}  // namespace fitfeel::cylindrical

namespace fitfeel::cylindrical {
namespace {

// Over many seeds of random form, the tabulated axis position under interference minimises the
// elastic energy sum(area * delta^2), computed here directly from the V arrays (equal row pitch,
// depths on the row grid, so every shaft row faces exactly one bushing row).
TEST(CylinderContact, InterferenceAxisMinimisesElasticEnergy) {
  int checked = 0;
  for (int seed = 0; seed < 40; ++seed) {
    std::mt19937_64 rng(100 + seed);
    const int ms = 12, mb = 6, n = 24;
    const double pitch = 2e-3, ls = ms * pitch, lb = mb * pitch;
    std::uniform_real_distribution<double> vs(-3 * kUm, 6 * kUm), vb(0.0, 5 * kUm);
    Eigen::VectorXd shaft_v(ms * n), bushing_v(mb * n);
    for (auto& v : shaft_v) v = vs(rng);
    for (auto& v : bushing_v) v = vb(rng);
    const PartSpec shaft = MakeShaft(0.020, ls), bushing = MakeBushing(0.020, lb, 0.030);
    const SurfaceGrid gs = MakeGrid(ms, n, 0.020, ls), gb = MakeGrid(mb, n, 0.020, lb);
    ModelSettings st = Settings(0.15, 0.0, TextureMode::kSampled);
    st.depth_step = pitch;
    CylinderContactAnalyzer a;
    a.Prepare(shaft, MakeSms(gs, [&](int i, int j) { return shaft_v[i * n + j]; }), bushing,
              MakeSms(gb, [&](int i, int j) { return bushing_v[i * n + j]; }), st);
    for (int k = 1; k < a.depth_steps() - 1; ++k) {
      const int first = k - ms;  // bushing row facing shaft row 0
      auto energy = [&](const Eigen::Vector2d& p) {
        double e = 0.0;
        for (int i = 0; i < ms; ++i) {
          const int b = first + i;
          if (b < 0 || b >= mb) continue;
          for (int j = 0; j < n; ++j) {
            const double beta = 2 * kPi * j / n;
            const double gap = bushing_v[b * n + j] - shaft_v[i * n + j] -
                               (p.x() * std::cos(beta) + p.y() * std::sin(beta));
            e += gs.area[0] * std::max(0.0, -gap) * std::max(0.0, -gap);
          }
        }
        return e;
      };
      if (!a.interference_at(k)) {
        EXPECT_LT(energy(a.anchor(k)), 1e-40) << "seed " << seed << " step " << k;
        continue;
      }
      ++checked;
      const Eigen::Vector2d p = a.anchor(k);
      const double e0 = energy(p);
      EXPECT_GT(e0, 0.0);
      for (int d = 0; d < 8; ++d) {
        const Eigen::Vector2d dir(std::cos(d * kPi / 4), std::sin(d * kPi / 4));
        for (double eps : {1e-9, 1e-7}) {
          EXPECT_GE(energy(p + eps * dir), e0 * (1 - 1e-12)) << "seed " << seed << " step " << k;
        }
      }
    }
  }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace fitfeel::cylindrical
