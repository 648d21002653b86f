#include "surfaces/cylindrical/cylindrical_coarse_mesh.h"

#include <cmath>
#include <memory>

#include "framework/collision/mesh_collider.h"
#include "framework/core/error.h"
#include "surfaces/cylindrical/test/test_parts.h"

#include <gtest/gtest.h>

namespace fitfeel::cylindrical {
namespace {

using testing::PaperHole;
using testing::PaperShaft;
using testing::Part;

PartSpec Hub(PartSpec hole, double outer_diameter) {
  hole.geometry = std::make_shared<CylindricalGeometry>(
      Role::kOuter, hole.size.nominal, hole.geometry->mating_length(), outer_diameter, 0.0);
  return hole;
}

TEST(CylindricalCoarseMeshTest, FacetsFollowTheFitsRadialZone) {
  // Paper Table 2: js6 (16 um) in 0/+25 um: (16 + 25) / 2 = 20.5 um on r = 10 mm:
  // pi / acos(1 - 20.5e-6 / 0.01) = 49.06 -> 50.
  EXPECT_EQ(CoarseFacets(PaperShaft(), PaperHole()), 50);
  // H7/g6 at 20 mm (ISO 286: H7 0/+21 um, g6 -20/-7 um): 17 um -> 54.
  const PartSpec g6 = Part("shaft", Role::kInner, 0.020, 0.050, -20e-6, -7e-6);
  const PartSpec h7 = Part("hole", Role::kOuter, 0.020, 0.030, 0.0, 21e-6);
  EXPECT_EQ(CoarseFacets(g6, h7), 54);
  EXPECT_LE(ChordalError(0.010, 54), 17e-6);
  // Exact parts: the finest mesh offered; loose ones: at least 8 facets.
  EXPECT_EQ(CoarseFacets(Part("s", Role::kInner, 0.02, 0.05, 0.0, 0.0),
                         Part("h", Role::kOuter, 0.02, 0.05, 0.0, 0.0)),
            kMaxCoarseFacets);
  EXPECT_EQ(CoarseFacets(Part("s", Role::kInner, 0.02, 0.05, -5e-3, 0.0),
                         Part("h", Role::kOuter, 0.02, 0.05, 0.0, 5e-3)),
            8);
}

TEST(CylindricalCoarseMeshTest, ShaftTrailsItsLeadingEndAndTheBushingStartsAtItsEntrance) {
  const PartSpec hole = Hub(PaperHole(), 0.030);
  const CoarseMeshes meshes = MakeCylindricalCoarseMeshes(PaperShaft(), hole);
  ASSERT_FALSE(meshes.empty());
  const int n = CoarseFacets(PaperShaft(), hole);
  EXPECT_EQ(meshes.inner.triangles.size(), 4u * n);
  EXPECT_EQ(meshes.outer.triangles.size(), 12u * n);  // a convex sector per facet
  double shaft_min_y = 0.0, shaft_max_y = -1.0, shaft_max_r = 0.0;
  for (const Eigen::Vector3d& v : meshes.inner.vertices) {
    shaft_min_y = std::min(shaft_min_y, v.y());
    shaft_max_y = std::max(shaft_max_y, v.y());
    shaft_max_r = std::max(shaft_max_r, std::hypot(v.x(), v.z()));
  }
  EXPECT_DOUBLE_EQ(shaft_min_y, -0.060);
  EXPECT_DOUBLE_EQ(shaft_max_y, 0.0);
  EXPECT_NEAR(shaft_max_r, 0.010, 1e-15);
  double hole_min_y = 1.0, hole_max_y = -1.0, hole_min_r = 1.0, hole_max_r = 0.0;
  for (const Eigen::Vector3d& v : meshes.outer.vertices) {
    hole_min_y = std::min(hole_min_y, v.y());
    hole_max_y = std::max(hole_max_y, v.y());
    hole_min_r = std::min(hole_min_r, std::hypot(v.x(), v.z()));
    hole_max_r = std::max(hole_max_r, std::hypot(v.x(), v.z()));
  }
  EXPECT_DOUBLE_EQ(hole_min_y, 0.0);
  EXPECT_DOUBLE_EQ(hole_max_y, 0.020);
  EXPECT_NEAR(hole_min_r, 0.010 / std::cos(M_PI / n), 1e-15);
  EXPECT_NEAR(hole_max_r, 0.015, 1e-15);
}

TEST(CylindricalCoarseMeshTest, ACentredShaftClearsTheBoreAndAnOffOneStrikesTheFace) {
  const PartSpec hole = Hub(PaperHole(), 0.030);
  const CoarseMeshes meshes = MakeCylindricalCoarseMeshes(PaperShaft(), hole);
  const MeshCollider collider(meshes.outer, meshes.inner);
  const std::unique_ptr<CollisionScratch> collider_scratch = collider.MakeScratch();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Penetration p;
  for (double y : {0.0, 1e-3, 0.019, 0.030}) {
    pose.translation() = Eigen::Vector3d(0.0, y, 0.0);
    collider.Query(pose, collider_scratch.get(), &p);
    EXPECT_FALSE(p.contact) << y;
  }
  pose.translation() = Eigen::Vector3d(0.0, 1e-4, 2e-3);
  collider.Query(pose, collider_scratch.get(), &p);
  EXPECT_TRUE(p.contact);
  EXPECT_NEAR(p.depth, 1e-4, 1e-12);
}

// The lead-in: 1 mm off the axis, the shaft's C0.5 end meets the bore's C1 entrance on the
// chamfers' 45 degree slope, which pushes it back and toward the axis alike; without chamfers the
// same pose strikes the flat face, which only pushes back.
TEST(CylindricalCoarseMeshTest, ChamfersTurnAnOffAxisShaftTowardTheAxis) {
  PartSpec shaft = PaperShaft();
  PartSpec hole = Hub(PaperHole(), 0.030);
  auto chamfered = [](const PartSpec& part, double length) {
    auto g = std::make_shared<CylindricalGeometry>(
        *static_cast<const CylindricalGeometry*>(part.geometry.get()));
    g->set_chamfer({length, M_PI / 4});
    PartSpec out = part;
    out.geometry = g;
    return out;
  };
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Penetration p;
  // Tip 0.6 mm past the entrance face (y = -1 mm: the chamfer lies in front of the bore), 1 mm
  // off the axis toward +x: the tip's edge (r 9.5 mm, reaching x = 10.5 mm) is 0.1 mm into the
  // entrance cone (r = 10 mm - y = 10.4 mm there).
  pose.translation() = Eigen::Vector3d(1e-3, -0.4e-3, 0.0);
  {
    const CoarseMeshes meshes = MakeCylindricalCoarseMeshes(chamfered(shaft, 0.5e-3),
                                                            chamfered(hole, 1e-3));
    EXPECT_EQ(meshes.inner.triangles.size(), 4u * CoarseFacets(shaft, hole) * 2);
    const MeshCollider collider(meshes.outer, meshes.inner, 256);
    const auto scratch = collider.MakeScratch();
    collider.Query(pose, scratch.get(), &p);
    ASSERT_TRUE(p.contact);
    // 0.1 mm radial overlap on a 45 degree slope: 0.0707 mm deep, within the facets' error.
    EXPECT_NEAR(p.depth, 0.1e-3 * std::sqrt(0.5), 0.02e-3);
    EXPECT_LT(p.normal.x(), -0.5);  // toward the axis
    EXPECT_LT(p.normal.y(), -0.5);  // and back out of the entrance
  }
  {
    // The sharp bore's face is at y = 0: the tip 0.6 mm past it, as above.
    const CoarseMeshes sharp = MakeCylindricalCoarseMeshes(shaft, hole);
    const MeshCollider collider(sharp.outer, sharp.inner, 256);
    const auto scratch = collider.MakeScratch();
    pose.translation().y() = 0.6e-3;
    collider.Query(pose, scratch.get(), &p);
    ASSERT_TRUE(p.contact);
    EXPECT_NEAR(p.normal.y(), -1.0, 1e-9);  // the face: straight back
    EXPECT_NEAR(p.normal.x(), 0.0, 1e-9);
  }
}

TEST(CylindricalCoarseMeshTest, RefusesAPartWithoutCylindricalGeometry) {
  PartSpec shaft = PaperShaft();
  shaft.geometry.reset();
  EXPECT_THROW(MakeCylindricalCoarseMeshes(shaft, PaperHole()), UserError);
}

}  // namespace
}  // namespace fitfeel::cylindrical
