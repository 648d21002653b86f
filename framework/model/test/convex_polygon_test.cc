#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "framework/model/convex_polygon.h"
#include "framework/testing/units.h"

// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

using Poly = std::vector<Eigen::Vector2d>;
using test_support::kPi;

// Reference: clip a large square by each half-plane in turn (Sutherland-Hodgman), O(n^2).
Poly ClipReference(const std::vector<double>& angle, const std::vector<double>& h) {
  Poly poly = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (std::size_t j = 0; j < angle.size() && !poly.empty(); ++j) {
    const Eigen::Vector2d u(std::cos(angle[j]), std::sin(angle[j]));
    Poly next;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Eigen::Vector2d& a = poly[k];
      const Eigen::Vector2d& b = poly[(k + 1) % poly.size()];
      const double fa = a.dot(u) - h[j], fb = b.dot(u) - h[j];
      if (fa <= 0) next.push_back(a);
      if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) next.push_back(a + (b - a) * (fa / (fa - fb)));
    }
    poly = next;
  }
  return poly;
}

double Area(const Poly& p) {
  double a = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto& u = p[k];
    const auto& v = p[(k + 1) % p.size()];
    a += u.x() * v.y() - u.y() * v.x();
  }
  return 0.5 * a;
}

std::vector<double> Angles(int n) {
  std::vector<double> a(n);
  for (int j = 0; j < n; ++j) a[j] = 2 * kPi * j / n;
  return a;
}

TEST(AssemblyPolygon, UniformClearanceIsRegularPolygonWithInscribedRadiusC) {
  for (int n : {3, 4, 7, 36, 360}) {
    const double c = 12.5e-6;
    Poly v;
    ASSERT_TRUE(IntersectHalfPlanes(Angles(n), std::vector<double>(n, c), 1.0, &v)) << n;
    ASSERT_EQ(static_cast<int>(v.size()), n);
    for (const auto& p : v) EXPECT_NEAR(p.norm(), c / std::cos(kPi / n), 1e-18) << n;
    // Inscribed radius: the extent along each normal is c, along each vertex c / cos(pi/n).
    for (int j = 0; j < n; ++j) {
      const double b = 2 * kPi * j / n;
      EXPECT_NEAR(RayExtent(v.data(), n, {std::cos(b), std::sin(b)}), c, 1e-18);
      const double bv = b + kPi / n;
      EXPECT_NEAR(RayExtent(v.data(), n, {std::cos(bv), std::sin(bv)}), c / std::cos(kPi / n),
                  1e-18);
    }
    const Eigen::Vector2d centre = PolygonCentroid(v.data(), n);
    EXPECT_LT(centre.norm(), 1e-18);
  }
}

TEST(AssemblyPolygon, AgreesWithClippingOverManySeeds) {
  int empties = 0, nonempties = 0;
  for (int seed = 0; seed < 400; ++seed) {
    std::mt19937_64 rng(seed);
    const int n = 3 + seed % 40;
    std::uniform_real_distribution<double> off(-4e-6, 10e-6);
    std::normal_distribution<double> centre(0.0, 5e-6);
    const Eigen::Vector2d o(centre(rng), centre(rng));
    std::vector<double> angle = Angles(n), h(n);
    // A shifted, noisy clearance: sometimes empty, sometimes not containing the origin.
    for (int j = 0; j < n; ++j)
      h[j] = off(rng) + o.dot(Eigen::Vector2d(std::cos(angle[j]), std::sin(angle[j])));
    Poly v;
    const bool ok = IntersectHalfPlanes(angle, h, 1.0, &v);
    const Poly ref = ClipReference(angle, h);
    const double ref_area = ref.size() >= 3 ? Area(ref) : 0.0;
    if (ref_area < 1e-24) {
      EXPECT_TRUE(!ok || std::abs(Area(v)) < 1e-22) << "seed " << seed;
      ++empties;
      continue;
    }
    ASSERT_TRUE(ok) << "seed " << seed << " area " << ref_area << " n " << n;
    ++nonempties;
    EXPECT_NEAR(Area(v), ref_area, 1e-6 * ref_area + 1e-26) << "seed " << seed;
    // Every vertex satisfies every constraint.
    for (const auto& p : v) {
      for (int j = 0; j < n; ++j) {
        EXPECT_LE(p.dot(Eigen::Vector2d(std::cos(angle[j]), std::sin(angle[j]))), h[j] + 1e-15);
      }
    }
    // Projection: inside points are fixed; an outside point's projection is no farther than any
    // sampled boundary point.
    std::uniform_real_distribution<double> q(-3e-5, 3e-5);
    for (int trial = 0; trial < 10; ++trial) {
      const Eigen::Vector2d x(q(rng), q(rng));
      const Eigen::Vector2d p = ProjectOntoPolygon(v.data(), static_cast<int>(v.size()), x);
      double best = 1e9;
      for (std::size_t k = 0; k < ref.size(); ++k) {
        const Eigen::Vector2d a = ref[k], e = ref[(k + 1) % ref.size()] - a;
        const double t = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (x - a - t * e).norm());
      }
      bool inside = true;
      for (int j = 0; j < n; ++j) {
        inside &= x.dot(Eigen::Vector2d(std::cos(angle[j]), std::sin(angle[j]))) <= h[j];
      }
      if (inside) {
        EXPECT_EQ(p, x);
      } else {
        EXPECT_NEAR((x - p).norm(), best, 1e-16 + 1e-9 * best) << "seed " << seed;
      }
    }
  }
  EXPECT_GT(empties, 20);
  EXPECT_GT(nonempties, 20);
}

TEST(AssemblyPolygon, FanQueriesAgreeWithTheLinearScans) {
  // The tick's logarithmic queries against the O(n) scans they replace, on the assembly spaces
  // the analyzers build (noisy, shifted, sometimes without the origin) and on points near and
  // far: the same distance to the polygon, the same extent along every ray.
  int fans = 0, origin_fans = 0;
  for (int seed = 0; seed < 400; ++seed) {
    std::mt19937_64 rng(seed);
    const int n = 3 + seed % 120;
    // A clearance of 0.5-10 um with form noise of up to 1 um, the axis shifted by a few um.
    const double clearance = std::uniform_real_distribution<double>(0.5e-6, 10e-6)(rng);
    std::uniform_real_distribution<double> noise(-1e-6, 1e-6);
    std::normal_distribution<double> shift(0.0, 4e-6);
    const Eigen::Vector2d o(shift(rng), shift(rng));
    std::vector<double> angle = Angles(n), h(n);
    for (int j = 0; j < n; ++j) {
      h[j] =
          clearance + noise(rng) + o.dot(Eigen::Vector2d(std::cos(angle[j]), std::sin(angle[j])));
    }
    Poly v;
    if (!IntersectHalfPlanes(angle, h, 1.0, &v)) continue;
    const int count = static_cast<int>(v.size());
    std::vector<double> a(v.size()), b(v.size());
    const Eigen::Vector2d centre = PolygonCentroid(v.data(), count);
    if (!FanAngles(v.data(), count, centre, a.data())) continue;
    ++fans;
    const PolygonFan fan{centre, a.data()};
    const bool has_origin = FanAngles(v.data(), count, Eigen::Vector2d::Zero(), b.data());
    origin_fans += has_origin;
    const PolygonFan at_origin{Eigen::Vector2d::Zero(), b.data()};
    for (double reach : {3e-6, 3e-5, 1e-3}) {
      std::uniform_real_distribution<double> q(-reach, reach);
      for (int trial = 0; trial < 25; ++trial) {
        const Eigen::Vector2d x = centre + Eigen::Vector2d(q(rng), q(rng));
        const Eigen::Vector2d linear = ProjectOntoPolygon(v.data(), count, x);
        const Eigen::Vector2d fast = ProjectOntoPolygon(v.data(), count, fan, x);
        EXPECT_NEAR((x - fast).norm(), (x - linear).norm(), 1e-12 * (x - linear).norm() + 1e-20)
            << "seed " << seed << " reach " << reach;
        if (has_origin) {
          const Eigen::Vector2d d = x.normalized();
          EXPECT_NEAR(RayExtent(v.data(), count, at_origin, d), RayExtent(v.data(), count, d),
                      1e-12 * RayExtent(v.data(), count, d))
              << "seed " << seed;
        }
      }
    }
  }
  EXPECT_GT(fans, 300);
  EXPECT_GT(origin_fans, 100);
}

TEST(AssemblyPolygon, ClosedToAPointStillPushesBack) {
  // Line-to-line fit: every h_j = 0, the polygon is the origin (several coincident vertices).
  for (int n : {3, 8, 36}) {
    Poly v;
    ASSERT_TRUE(IntersectHalfPlanes(Angles(n), std::vector<double>(n, 0.0), 1.0, &v));
    const Eigen::Vector2d x(1e-6, -2e-6);
    const Eigen::Vector2d p = ProjectOntoPolygon(v.data(), static_cast<int>(v.size()), x);
    EXPECT_LT(p.norm(), 1e-18) << n;
  }
  // A segment: two anti-parallel pairs squeezed to x = 1 um, |z| <= 2 um.
  std::vector<double> h = {1e-6, 2e-6, -1e-6, 2e-6};
  Poly v;
  ASSERT_TRUE(IntersectHalfPlanes(Angles(4), h, 1.0, &v));
  const Eigen::Vector2d p = ProjectOntoPolygon(v.data(), static_cast<int>(v.size()), {1e-6, 5e-6});
  EXPECT_NEAR((p - Eigen::Vector2d(1e-6, 2e-6)).norm(), 0.0, 1e-18);
}

TEST(AssemblyPolygon, OppositeConstraintsThatCrossAreEmpty) {
  // A shaft 1 um too fat on one diameter only: h = +5 um everywhere but -3 um at 0 and pi.
  const int n = 8;
  std::vector<double> h(n, 5e-6);
  h[0] = -3e-6;
  h[4] = -3e-6;
  Poly v;
  EXPECT_FALSE(IntersectHalfPlanes(Angles(n), h, 1.0, &v));
  h[4] = 4e-6;  // now -4 um <= x <= -3 um: a thin polygon
  EXPECT_TRUE(IntersectHalfPlanes(Angles(n), h, 1.0, &v));
}

// The fans' pseudo-angle orders directions as their angles do: 0, 1, 2, 3 on the axes, and for
// 20 000 random directions (some on or next to the axes) the sorted order of atan2 on [0, 2 pi).
TEST(PseudoAngle, OrdersDirectionsAsTheirAngles) {
  EXPECT_EQ(PseudoAngle({1.0, 0.0}), 0.0);
  EXPECT_EQ(PseudoAngle({0.0, 2.0}), 1.0);
  EXPECT_EQ(PseudoAngle({-3.0, 0.0}), 2.0);
  EXPECT_EQ(PseudoAngle({0.0, -1e-9}), 3.0);
  EXPECT_EQ(PseudoAngle({0.0, 0.0}), 0.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::pair<double, double>> both;  // (angle on [0, 2 pi), pseudo-angle)
  for (int i = 0; i < 20000; ++i) {
    Eigen::Vector2d d(u(rng), u(rng));
    if (i % 10 == 0) d[i % 20 == 0 ? 0 : 1] = 1e-300 * u(rng);  // on or next to an axis
    if (d.isZero()) continue;
    double a = std::atan2(d.y(), d.x());
    if (a < 0.0) a += 2.0 * std::numbers::pi;
    if (a >= 2.0 * std::numbers::pi) a = 0.0;  // a hair below +x rounds to a whole turn
    const double p = PseudoAngle(d);
    EXPECT_GE(p, 0.0);
    EXPECT_LT(p, kPseudoTurn);
    both.emplace_back(a, p);
  }
  std::sort(both.begin(), both.end());
  for (std::size_t i = 1; i < both.size(); ++i) {
    EXPECT_LE(both[i - 1].second, both[i].second) << both[i - 1].first << " " << both[i].first;
  }
}

}  // namespace
}  // namespace fitfeel
