#include "framework/collision/coarse_mesh.h"

#include <cmath>

#include "framework/core/error.h"

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

// Signed volume by the divergence theorem: positive and equal to the solid's volume only when
// every triangle is wound counter-clockwise from outside and the mesh is closed.
double SignedVolume(const TriangleMesh& mesh) {
  double v = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    v += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6.0;
  }
  return v;
}

double PolygonArea(double vertex_radius, int n) {
  return 0.5 * n * vertex_radius * vertex_radius * std::sin(2.0 * M_PI / n);
}

TEST(CoarseMeshTest, FacetCountMeetsTheChordalBoundAndIsTheSmallestThatDoes) {
  for (double r : {1e-3, 5e-3, 10e-3, 50e-3}) {
    for (double e : {1e-6, 5e-6, 2e-5, 1e-4}) {
      const int n = FacetsForChordalError(r, e);
      EXPECT_LE(ChordalError(r, n), e);
      if (n > 8) {
        EXPECT_GT(ChordalError(r, n - 1), e);
      }
    }
  }
  // r = 10 mm, 17 um: pi / acos(1 - 0.0017) = 53.9 -> 54.
  EXPECT_EQ(FacetsForChordalError(10e-3, 17e-6), 54);
  EXPECT_EQ(FacetsForChordalError(10e-3, 1.0), 8);
  EXPECT_THROW(FacetsForChordalError(10e-3, 0.0), UserError);
  EXPECT_THROW(FacetsForChordalError(-1.0, 1e-6), UserError);
  EXPECT_THROW(FacetsForChordalError(1.0, 1e-12), UserError);
}

TEST(CoarseMeshTest, ClosedCylinderIsClosedOutwardAndOfThePrismsVolume) {
  const int n = 40;
  const TriangleMesh m = MakeClosedCylinder(10e-3, -30e-3, 0.0, n);
  EXPECT_EQ(m.triangles.size(), 4u * n);
  EXPECT_NEAR(SignedVolume(m), PolygonArea(10e-3, n) * 30e-3, 1e-15);
  for (const Eigen::Vector3d& v : m.vertices) {
    EXPECT_LE(std::hypot(v.x(), v.z()), 10e-3 * (1 + 1e-12));
    EXPECT_GE(v.y(), -30e-3);
    EXPECT_LE(v.y(), 0.0);
  }
  EXPECT_THROW(MakeClosedCylinder(10e-3, 0.0, 0.0, n), UserError);
  EXPECT_THROW(MakeClosedCylinder(0.0, 0.0, 1.0, n), UserError);
  EXPECT_THROW(MakeClosedCylinder(1.0, 0.0, 1.0, 2), UserError);
}

TEST(CoarseMeshTest, TubeKeepsItsMaterialOutsideTheInnerCircle) {
  const int n = 54;
  const double ri = 10e-3, ro = 20e-3;
  const TriangleMesh m = MakeTube(ri, ro, 0.0, 40e-3, n);
  // A closed hexahedron per facet: eight corners, twelve triangles.
  ASSERT_EQ(m.vertices.size(), 8u * n);
  EXPECT_EQ(m.triangles.size(), 12u * n);
  const double inner_vertex = ri / std::cos(M_PI / n);
  EXPECT_NEAR(SignedVolume(m), (PolygonArea(ro, n) - PolygonArea(inner_vertex, n)) * 40e-3, 1e-15);
  for (int i = 0; i < n; ++i) {
    // Each sector closed and wound outward on its own: its volume is the tube's n-th.
    TriangleMesh sector;
    sector.vertices.assign(m.vertices.begin() + 8 * i, m.vertices.begin() + 8 * i + 8);
    for (int t = 0; t < 12; ++t) {
      sector.triangles.push_back(m.triangles[static_cast<std::size_t>(12 * i + t)] -
                                 Eigen::Vector3i::Constant(8 * i));
    }
    EXPECT_NEAR(SignedVolume(sector),
                (PolygonArea(ro, n) - PolygonArea(inner_vertex, n)) * 40e-3 / n, 1e-16);
    // Its bore facet's mid-point (its closest point to the axis) is on the inner circle.
    const double mid = 2.0 * M_PI * (i + 0.5) / n;
    const Eigen::Vector3d c = 0.5 * (m.vertices[8 * i] + m.vertices[8 * i + 2]);
    EXPECT_NEAR(std::hypot(c.x(), c.z()), ri, 1e-12);
    EXPECT_NEAR(std::atan2(c.z(), c.x()), std::remainder(mid, 2.0 * M_PI), 1e-9);
  }
  EXPECT_THROW(MakeTube(20e-3, 20e-3, 0.0, 1.0, n), UserError);
  EXPECT_THROW(MakeTube(0.0, 20e-3, 0.0, 1.0, n), UserError);
}

}  // namespace
}  // namespace fitfeel
