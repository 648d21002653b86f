#include "framework/collision/mesh_collider.h"

#include <cmath>
#include <memory>
#include <random>

#include "framework/core/error.h"
#include "framework/testing/allocation_counter.h"
#include "framework/testing/solid_tube.h"

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

constexpr int kTubeFacets = 54;
constexpr double kTubeRadius = 10e-3;

Eigen::Isometry3d Placed(double x, double y, double z) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  return t;
}

// A 20 mm bushing (hub 40 mm, 40 mm long) and a 60 mm shaft of the same nominal diameter: as
// convex pieces, or with the bushing one solid (FCL).
MeshCollider MakePair(bool pieces = true, int max_contacts = 64) {
  return MeshCollider(pieces ? MakeTube(kTubeRadius, 20e-3, 0.0, 40e-3, kTubeFacets)
                             : test_support::SolidTube(kTubeRadius, 20e-3, 0.0, 40e-3, kTubeFacets),
                      MakeClosedCylinder(kTubeRadius, -60e-3, 0.0, kTubeFacets), max_contacts);
}

TEST(MeshColliderTest, ConvexPiecesWhereEverySolidIsConvex) {
  EXPECT_TRUE(MakePair(true).convex_pieces());
  EXPECT_FALSE(MakePair(false).convex_pieces());
  TriangleMesh two = MakeClosedCylinder(kTubeRadius, -60e-3, -1e-3, kTubeFacets);
  AppendMesh(MakeClosedFrustum(kTubeRadius, kTubeRadius - 1e-3, -1e-3, 0.0, kTubeFacets), &two);
  EXPECT_TRUE(
      MeshCollider(MakeTube(kTubeRadius, 20e-3, 0.0, 40e-3, kTubeFacets), two).convex_pieces());
  EXPECT_TRUE(
      MeshCollider(MakeTaperedTube(kTubeRadius + 1e-3, kTubeRadius, 20e-3, -1e-3, 0.0, kTubeFacets),
                   two)
          .convex_pieces());
}

TEST(MeshColliderTest, FarAwayIsFree) {
  for (bool pieces : {true, false}) {
    const MeshCollider collider = MakePair(pieces);
    const std::unique_ptr<CollisionScratch> collider_scratch = collider.MakeScratch();
    Penetration p;
    collider.Query(Placed(0.0, -5e-3, 0.0), collider_scratch.get(), &p);
    EXPECT_FALSE(p.contact);
    collider.Query(Placed(50e-3, 30e-3, 0.0), collider_scratch.get(), &p);  // beside the hub
    EXPECT_FALSE(p.contact);
    EXPECT_EQ(p.depth, 0.0);
    EXPECT_EQ(p.normal, Eigen::Vector3d::Zero());
  }
}

TEST(MeshColliderTest, AnEndOnTheFaceReportsItsDepthAndPushesBackAlongMinusY) {
  for (bool pieces : {true, false}) {
    const MeshCollider collider = MakePair(pieces);
    const std::unique_ptr<CollisionScratch> collider_scratch = collider.MakeScratch();
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> radial(1.2 * kTubeRadius, 1.9 * kTubeRadius);
    std::uniform_real_distribution<double> angle(-M_PI, M_PI);
    std::uniform_real_distribution<double> depth(1e-7, 2e-3);
    for (int i = 0; i < 200; ++i) {
      // The end disc overlaps the annular face but the shaft clears the hub's outside wall only
      // partly: the face is struck whatever the offset.
      const double r = radial(gen), a = angle(gen), y = depth(gen);
      Penetration p;
      collider.Query(Placed(r * std::cos(a), y, r * std::sin(a)), collider_scratch.get(), &p);
      ASSERT_TRUE(p.contact) << "r " << r << " y " << y;
      // A flat end on a flat face: exact (no chordal error enters along y).
      EXPECT_NEAR(p.depth, y, 1e-12 + 1e-9 * y);
      EXPECT_NEAR(p.normal.y(), -1.0, 1e-12);
      // The force acts in the overlapping slab 0 <= y <= depth: in its middle for the pieces, at
      // FCL's contact point (on the end) otherwise.
      EXPECT_NEAR(p.point.y(), pieces ? 0.5 * y : y, 1e-9);
    }
  }
}

TEST(MeshColliderTest, ACentredShaftPassesTheEntrance) {
  const double slack = ChordalError(kTubeRadius, kTubeFacets);
  for (bool pieces : {true, false}) {
    const MeshCollider collider = MakePair(pieces);
    const std::unique_ptr<CollisionScratch> collider_scratch = collider.MakeScratch();
    Penetration p;
    for (double y : {-1e-3, 0.0, 1e-6, 1e-3, 20e-3, 39e-3}) {
      collider.Query(Placed(0.0, y, 0.0), collider_scratch.get(), &p);
      EXPECT_FALSE(p.contact) << y;
    }
    // The meshes are similar polygons, the bore's scaled by 1 / cos(pi / n): a radial slack of
    // the chordal error r (1 - cos(pi / n)) in every direction, less at a vertex-facing direction.
    for (int i = 0; i < 16; ++i) {
      const double a = 2.0 * M_PI * i / 16;
      collider.Query(Placed(0.5 * slack * std::cos(a), 10e-3, 0.5 * slack * std::sin(a)),
                     collider_scratch.get(), &p);
      EXPECT_FALSE(p.contact) << a;
    }
  }
  // Far enough off the axis, the shaft's wall enters the bore's: pushed back towards the axis by
  // the offset less the slack. The shaft's faces are parallel to the bore's, so it is free where
  // its offset's projection on every facet normal is at most the slack: a polygon whose
  // inscribed radius is the slack and whose corners lie at slack / cos(pi / n). The true way out
  // is the distance to that polygon, between s - slack / cos(pi / n) and s - slack, along a facet
  // normal within pi / n of the offset's direction (or towards a corner). The convex pieces find
  // it to within what the neighbouring sectors add. FCL sees the shaft overlap the solid bore in
  // hundreds of triangle pairs, of which the query sees the first max_contacts: with all of them
  // (256) a facet normal within 2 pi / n and the depth within the chordal error; with the default
  // 64, measured on this pair, within 20 degrees and one chordal error.
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::uniform_real_distribution<double> offset(3.0 * slack, 0.3e-3);
  const MeshCollider collider = MakePair(true);
  const MeshCollider fcl = MakePair(false);
  const MeshCollider exhaustive = MakePair(false, 256);
  const std::unique_ptr<CollisionScratch> collider_scratch = collider.MakeScratch();
  const std::unique_ptr<CollisionScratch> fcl_scratch = fcl.MakeScratch();
  const std::unique_ptr<CollisionScratch> exhaustive_scratch = exhaustive.MakeScratch();
  Penetration p;
  for (int i = 0; i < 50; ++i) {
    const double a = angle(gen), s = offset(gen);
    const Eigen::Vector3d inward(-std::cos(a), 0.0, -std::sin(a));
    const Eigen::Isometry3d pose = Placed(s * std::cos(a), 10e-3, s * std::sin(a));
    collider.Query(pose, collider_scratch.get(), &p);
    ASSERT_TRUE(p.contact);
    EXPECT_GE(p.depth, s - slack / std::cos(M_PI / kTubeFacets)) << s;
    EXPECT_LE(p.depth, s - 0.5 * slack) << s;
    EXPECT_GE(p.normal.dot(inward), std::cos(2.0 * M_PI / kTubeFacets)) << a;
    exhaustive.Query(pose, exhaustive_scratch.get(), &p);
    ASSERT_TRUE(p.contact);
    EXPECT_GE(p.depth, s - slack) << s;
    EXPECT_LE(p.depth, s + 0.5 * slack) << s;
    EXPECT_GE(p.normal.dot(inward), std::cos(2.0 * M_PI / kTubeFacets)) << a;
    fcl.Query(pose, fcl_scratch.get(), &p);
    ASSERT_TRUE(p.contact);
    EXPECT_GE(p.depth, s - slack) << s;
    EXPECT_LE(p.depth, s + slack) << s;
    EXPECT_GE(p.normal.dot(inward), std::cos(20.0 * M_PI / 180.0)) << a;
  }
}

// The way out the convex pieces report is one: moved by it (and a nanometre) the part is free,
// wherever it was against the face, in the bore or into its wall, as far as a hand gets in a few
// ticks (2 mm). (Held straight: a part tilted across the bore may touch both sides, which no
// translation undoes; and one pushed deep into the hub's material may leave the pieces it is in
// along an axis that leads into others.)
TEST(MeshColliderTest, ThePiecesWayOutFreesThePart) {
  const MeshCollider collider = MakePair(true);
  const std::unique_ptr<CollisionScratch> scratch = collider.MakeScratch();
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int contacts = 0;
  for (int i = 0; i < 3000; ++i) {
    // By turns: the end near the face outside the bore (tilted up to 3 degrees), in the bore off
    // the axis (straight), beside the hub's outer wall (tilted).
    const int family = i % 3;
    const double angle = 2.0 * M_PI * unit(gen);
    const double r = family == 0 ? 11e-3 + 19e-3 * unit(gen)
                                 : (family == 1 ? 2.5e-3 * unit(gen) : 29e-3 + 3e-3 * unit(gen));
    const double y = family == 0 ? -0.5e-3 + 2.5e-3 * unit(gen) : 2e-3 + 43e-3 * unit(gen);
    Eigen::Isometry3d pose = Placed(r * std::cos(angle), y, r * std::sin(angle));
    if (family != 1) {
      const double tilt = 0.05 * (2.0 * unit(gen) - 1.0), about = 2.0 * M_PI * unit(gen);
      pose.linear() =
          Eigen::AngleAxisd(tilt, Eigen::Vector3d(std::cos(about), 0.0, std::sin(about)))
              .toRotationMatrix();
    }
    Penetration p;
    collider.Query(pose, scratch.get(), &p);
    if (!p.contact || p.depth > 2e-3) continue;
    ++contacts;
    ASSERT_GT(p.depth, 0.0);
    ASSERT_NEAR(p.normal.norm(), 1.0, 1e-12);
    Eigen::Isometry3d out = pose;
    out.translation() += (p.depth + 1e-9) * p.normal;
    Penetration after;
    collider.Query(out, scratch.get(), &after);
    EXPECT_FALSE(after.contact) << i << " at " << pose.translation().transpose() << " depth "
                                << p.depth << " along " << p.normal.transpose() << " then "
                                << after.depth << " along " << after.normal.transpose();
  }
  EXPECT_GT(contacts, 1000);
}

TEST(MeshColliderTest, RefusesBadMeshes) {
  TriangleMesh bad = MakeClosedCylinder(kTubeRadius, -1e-3, 0.0, 8);
  bad.triangles.front()[0] = 1000;
  EXPECT_THROW(MeshCollider(MakeTube(kTubeRadius, 20e-3, 0.0, 1e-3, 8), bad), UserError);
  EXPECT_THROW(MeshCollider(TriangleMesh{}, MakeClosedCylinder(kTubeRadius, -1e-3, 0.0, 8)),
               UserError);
  EXPECT_THROW(MeshCollider(MakeTube(kTubeRadius, 20e-3, 0.0, 1e-3, 8),
                            MakeClosedCylinder(kTubeRadius, -1e-3, 0.0, 8), 0),
               UserError);
  TriangleMesh nan = MakeClosedCylinder(kTubeRadius, -1e-3, 0.0, 8);
  nan.vertices.front().x() = std::nan("");
  EXPECT_THROW(MeshCollider(MakeTube(kTubeRadius, 20e-3, 0.0, 1e-3, 8), nan), UserError);
}

TEST(MeshColliderTest, CounterSeesAllocations) {
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  auto probe = std::make_unique<double>(1.0);
  allocations.Stop();
  EXPECT_EQ(allocations.count(), 1);
}

// FCL's collide fills a std::vector of contacts and builds its traversal node on the stack; with
// the contact buffer grown once at construction, a query must not reach operator new; nor may
// the pieces' (their scratch is sized for the pair).
TEST(MeshColliderTest, QueriesDoNotAllocate) {
  for (bool pieces : {true, false}) {
    const MeshCollider collider = MakePair(pieces);
    const std::unique_ptr<CollisionScratch> collider_scratch = collider.MakeScratch();
    Penetration p;
    int in_contact = 0;
    FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
    test_support::ScopedAllocationCounter allocations;
    for (int k = 0; k < 2000; ++k) {
      const double x = 15e-3 * std::sin(k * 0.01);
      const double y = 2e-3 * std::cos(k * 0.013);
      collider.Query(Placed(x, y, 0.0), collider_scratch.get(), &p);
      in_contact += p.contact ? 1 : 0;
    }
    allocations.Stop();
    EXPECT_GT(in_contact, 100);  // both branches were exercised
    EXPECT_LT(in_contact, 1900);
    EXPECT_EQ(allocations.count(), 0);
  }
}

}  // namespace
}  // namespace fitfeel
