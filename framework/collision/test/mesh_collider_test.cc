#include "framework/collision/mesh_collider.h"

#include <cmath>
#include <memory>
#include <random>

#include "framework/core/error.h"
#include "framework/testing/allocation_counter.h"

#include <gtest/gtest.h>

FITFEEL_COUNT_ALLOCATIONS();

namespace fitfeel {
namespace {

constexpr int kFacets = 54;
constexpr double kRadius = 10e-3;

Eigen::Isometry3d At(double x, double y, double z) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  return t;
}

// A 20 mm bushing (hub 40 mm, 40 mm long) and a 60 mm shaft of the same nominal diameter.
MeshCollider MakePair() {
  return MeshCollider(MakeTube(kRadius, 20e-3, 0.0, 40e-3, kFacets),
                      MakeClosedCylinder(kRadius, -60e-3, 0.0, kFacets));
}

TEST(MeshColliderTest, FarAwayIsFree) {
  const MeshCollider collider = MakePair();
  const std::unique_ptr<CollisionScratch> collider_scratch = collider.MakeScratch();
  Penetration p;
  collider.Query(At(0.0, -5e-3, 0.0), collider_scratch.get(), &p);
  EXPECT_FALSE(p.contact);
  collider.Query(At(50e-3, 30e-3, 0.0), collider_scratch.get(), &p);  // beside the hub
  EXPECT_FALSE(p.contact);
  EXPECT_EQ(p.depth, 0.0);
  EXPECT_EQ(p.normal, Eigen::Vector3d::Zero());
}

TEST(MeshColliderTest, AnEndOnTheFaceReportsItsDepthAndPushesBackAlongMinusY) {
  const MeshCollider collider = MakePair();
  const std::unique_ptr<CollisionScratch> collider_scratch = collider.MakeScratch();
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> radial(1.2 * kRadius, 1.9 * kRadius);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::uniform_real_distribution<double> depth(1e-7, 2e-3);
  for (int i = 0; i < 200; ++i) {
    // The end disc overlaps the annular face but the shaft clears the hub's outside wall only
    // partly: the face is struck whatever the offset.
    const double r = radial(gen), a = angle(gen), y = depth(gen);
    Penetration p;
    collider.Query(At(r * std::cos(a), y, r * std::sin(a)), collider_scratch.get(), &p);
    ASSERT_TRUE(p.contact) << "r " << r << " y " << y;
    // A flat end on a flat face: exact (no chordal error enters along y).
    EXPECT_NEAR(p.depth, y, 1e-12 + 1e-9 * y);
    EXPECT_NEAR(p.normal.y(), -1.0, 1e-12);
    EXPECT_NEAR(p.point.y(), y, 1e-9);
  }
}

TEST(MeshColliderTest, ACentredShaftPassesTheEntrance) {
  const MeshCollider collider = MakePair();
  const std::unique_ptr<CollisionScratch> collider_scratch = collider.MakeScratch();
  Penetration p;
  for (double y : {-1e-3, 0.0, 1e-6, 1e-3, 20e-3, 39e-3}) {
    collider.Query(At(0.0, y, 0.0), collider_scratch.get(), &p);
    EXPECT_FALSE(p.contact) << y;
  }
  // The meshes are similar polygons, the bore's scaled by 1 / cos(pi / n): a radial slack of the
  // chordal error r (1 - cos(pi / n)) in every direction, less at a vertex-facing direction.
  const double slack = ChordalError(kRadius, kFacets);
  for (int i = 0; i < 16; ++i) {
    const double a = 2.0 * M_PI * i / 16;
    collider.Query(At(0.5 * slack * std::cos(a), 10e-3, 0.5 * slack * std::sin(a)), collider_scratch.get(), &p);
    EXPECT_FALSE(p.contact) << a;
  }
  // Far enough off the axis, the shaft's wall enters the bore's: pushed back towards the axis by
  // the offset less the slack. The shaft overlaps the bore over most of half its circumference,
  // hundreds of triangle pairs, of which the query sees the first max_contacts: with all of them
  // (256) the way out is a facet normal within 2 pi / n of the offset's direction and the depth
  // within the chordal error; with the default 64, measured on this pair, within 20 degrees and
  // one chordal error.
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::uniform_real_distribution<double> offset(3.0 * slack, 0.3e-3);
  const MeshCollider exhaustive(MakeTube(kRadius, 20e-3, 0.0, 40e-3, kFacets),
                                MakeClosedCylinder(kRadius, -60e-3, 0.0, kFacets), 256);
  const std::unique_ptr<CollisionScratch> exhaustive_scratch = exhaustive.MakeScratch();
  for (int i = 0; i < 50; ++i) {
    const double a = angle(gen), s = offset(gen);
    const Eigen::Vector3d inward(-std::cos(a), 0.0, -std::sin(a));
    exhaustive.Query(At(s * std::cos(a), 10e-3, s * std::sin(a)), exhaustive_scratch.get(), &p);
    ASSERT_TRUE(p.contact);
    EXPECT_GE(p.depth, s - slack) << s;
    EXPECT_LE(p.depth, s + 0.5 * slack) << s;
    EXPECT_GE(p.normal.dot(inward), std::cos(2.0 * M_PI / kFacets)) << a;
    collider.Query(At(s * std::cos(a), 10e-3, s * std::sin(a)), collider_scratch.get(), &p);
    ASSERT_TRUE(p.contact);
    EXPECT_GE(p.depth, s - slack) << s;
    EXPECT_LE(p.depth, s + slack) << s;
    EXPECT_GE(p.normal.dot(inward), std::cos(20.0 * M_PI / 180.0)) << a;
  }
}

TEST(MeshColliderTest, RefusesBadMeshes) {
  TriangleMesh bad = MakeClosedCylinder(kRadius, -1e-3, 0.0, 8);
  bad.triangles.front()[0] = 1000;
  EXPECT_THROW(MeshCollider(MakeTube(kRadius, 20e-3, 0.0, 1e-3, 8), bad), UserError);
  EXPECT_THROW(MeshCollider(TriangleMesh{}, MakeClosedCylinder(kRadius, -1e-3, 0.0, 8)), UserError);
  EXPECT_THROW(MeshCollider(MakeTube(kRadius, 20e-3, 0.0, 1e-3, 8),
                            MakeClosedCylinder(kRadius, -1e-3, 0.0, 8), 0),
               UserError);
}

TEST(MeshColliderTest, CounterSeesAllocations) {
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  auto probe = std::make_unique<double>(1.0);
  allocations.Stop();
  EXPECT_EQ(allocations.count(), 1);
}

// FCL's collide fills a std::vector of contacts and builds its traversal node on the stack; with
// the contact buffer grown once at construction, a query must not reach operator new.
TEST(MeshColliderTest, QueriesDoNotAllocate) {
  const MeshCollider collider = MakePair();
  const std::unique_ptr<CollisionScratch> collider_scratch = collider.MakeScratch();
  Penetration p;
  int in_contact = 0;
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  for (int k = 0; k < 2000; ++k) {
    const double x = 15e-3 * std::sin(k * 0.01);
    const double y = 2e-3 * std::cos(k * 0.013);
    collider.Query(At(x, y, 0.0), collider_scratch.get(), &p);
    in_contact += p.contact ? 1 : 0;
  }
  allocations.Stop();
  EXPECT_GT(in_contact, 100);  // both branches were exercised
  EXPECT_LT(in_contact, 1900);
  EXPECT_EQ(allocations.count(), 0);
}

}  // namespace
}  // namespace fitfeel
