// The thread's render mesh: every corner on its flank's helicoid, each cell the (theta, r)
// rectangle of its grid cell, the bolt's slid along its helix so that its leading end lies at the
// origin (the analyzer's frame), and the mesh as the plugin hands it to a viewer.
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/thread/thread_geometry.h"
#include "surfaces/thread/thread_shape.h"
#include "surfaces/thread/thread_surface.h"

namespace fitfeel::thread {
// Named: the suite is one unity source, whose other files have helpers of the same names.
namespace render_mesh_test {

constexpr double kPi = std::numbers::pi;

// M10 x 1.5, 60 deg: a bolt of 15 mm and a nut of 8.4 mm (5.6 turns, so that sliding the bolt
// along its helix by its turns also turns it).
PartSpec Part(Role role) {
  PartSpec p;
  p.name = role == Role::kInner ? "bolt" : "nut";
  p.role = role;
  p.size = {10e-3, 0.0, 0.0, ""};
  p.material = {"steel", 210e9, 0.3};
  p.form.declared = {{"pitch_error", 0.0}, {"flank_angle_error", 0.0}};
  const double length = role == Role::kInner ? 15.1e-3 : 8.4e-3;
  p.geometry = std::make_shared<HelicoidGeometry>(role, 10e-3, 1.5e-3, kPi / 3, length);
  return p;
}

// The angle from a to b, in (-pi, pi].
double AngleFrom(double a, double b) { return std::remainder(b - a, 2.0 * kPi); }

double Theta(const Eigen::Vector3d& p) { return std::atan2(-p.z(), p.x()); }
double Radius(const Eigen::Vector3d& p) { return std::hypot(p.x(), p.z()); }

std::string PartName(const ::testing::TestParamInfo<Role>& param) {
  return param.param == Role::kInner ? "Bolt" : "Nut";
}

class HelicoidRenderMeshTest : public ::testing::TestWithParam<Role> {};

TEST_P(HelicoidRenderMeshTest, CornersOnTheHelicoidAroundTheGridCells) {
  const PartSpec part = Part(GetParam());
  const HelicoidGeometry& g = HelicoidGeometryOf(part);
  const SurfaceGrid grid = HelicoidDiscretizer().Discretize(part, Resolution{45, 6});
  const RenderMesh mesh = ThreadSurface().MakeRenderMesh(part, grid);
  ASSERT_EQ(mesh.corners.size(), 4u * grid.size());
  ASSERT_EQ(mesh.directions.size(), static_cast<std::size_t>(grid.size()));
  const double pitch = g.pitch(), c = pitch / (2 * kPi), k = std::tan(g.half_angle());
  const double rp = g.pitch_radius(), dtheta = 2 * kPi * g.turns() / grid.rows;
  const double dr = (g.outer_radius() - g.inner_radius()) / 3;
  // The bolt's frame: its grid turned by -turns about +y and moved back by its length.
  const double start = part.role == Role::kInner ? -2 * kPi * g.turns() : 0.0;
  const double cs = std::cos(start), sn = std::sin(start);
  const auto slid = [&](const Eigen::Vector3d& v, double shift) {
    return Eigen::Vector3d(cs * v.x() + sn * v.z(), v.y() + shift, -sn * v.x() + cs * v.z());
  };
  for (int cell = 0; cell < grid.size(); ++cell) {
    const double s = cell % grid.columns < grid.columns / 2 ? 1.0 : -1.0;
    const auto corner = [&](int q) { return mesh.corners[4 * static_cast<std::size_t>(cell) + q]; };
    for (int q = 0; q < 4; ++q) {
      const Eigen::Vector3d p = corner(q);
      // On the helicoid y = c theta + s (P/4 - k (r - rp)), theta known up to whole turns.
      const double y = c * Theta(p) + s * (0.25 * pitch - k * (Radius(p) - rp));
      EXPECT_NEAR(std::remainder(p.y() - y, pitch), 0.0, 1e-15) << "cell " << cell << " " << q;
      EXPECT_GE(Radius(p), g.inner_radius() - 1e-15);
      EXPECT_LE(Radius(p), g.outer_radius() + 1e-15);
    }
    // The corners span the cell's dtheta and dr, going round it.
    EXPECT_NEAR(AngleFrom(Theta(corner(0)), Theta(corner(3))), dtheta, 1e-12);
    EXPECT_NEAR(AngleFrom(Theta(corner(1)), Theta(corner(2))), dtheta, 1e-12);
    EXPECT_NEAR(Radius(corner(1)) - Radius(corner(0)), dr, 1e-15);
    EXPECT_NEAR(Radius(corner(2)) - Radius(corner(3)), dr, 1e-15);
    // The grid's centre (slid as the mesh is) at the middle of the cell's (theta, r) rectangle,
    // where y, linear in theta and r, is the mean of the diagonal's ends.
    const Eigen::Vector3d centre = slid(grid.centre.col(cell), c * start);
    EXPECT_NEAR(AngleFrom(Theta(corner(0)), Theta(centre)), 0.5 * dtheta, 1e-12);
    EXPECT_NEAR(Radius(centre), 0.5 * (Radius(corner(0)) + Radius(corner(2))), 1e-15);
    EXPECT_NEAR(centre.y(), 0.5 * (corner(0).y() + corner(2).y()), 1e-15);
    EXPECT_NEAR(centre.y(), 0.5 * (corner(1).y() + corner(3).y()), 1e-15);
    // The direction is the grid's normal, turned with the slide: across both diagonals.
    const Eigen::Vector3d n = mesh.directions[static_cast<std::size_t>(cell)];
    EXPECT_NEAR((n - slid(grid.normal.col(cell), 0.0)).norm(), 0.0, 1e-15);
    EXPECT_LT(std::abs(n.dot((corner(2) - corner(0)).normalized())), 0.01);
    EXPECT_LT(std::abs(n.dot((corner(3) - corner(1)).normalized())), 0.01);
  }
}

INSTANTIATE_TEST_SUITE_P(BoltAndNut, HelicoidRenderMeshTest,
                         ::testing::Values(Role::kInner, Role::kOuter), PartName);

// The bolt's leading end at y = 0 and its body behind it; the nut from its entrance at y = 0 on.
TEST(HelicoidRenderMeshFrameTest, BoltEndsAtTheOriginAndTheNutStartsThere) {
  for (const Role role : {Role::kInner, Role::kOuter}) {
    const PartSpec part = Part(role);
    const HelicoidGeometry& g = HelicoidGeometryOf(part);
    const RenderMesh mesh =
        HelicoidRenderMesh(part, HelicoidDiscretizer().Discretize(part, Resolution{}));
    double low = INFINITY, high = -INFINITY;
    for (const Eigen::Vector3d& p : mesh.corners) {
      low = std::min(low, p.y());
      high = std::max(high, p.y());
    }
    // A flank reaches P/4 + k (rp - r1) either side of its helix point c theta.
    const double band =
        0.25 * g.pitch() + std::tan(g.half_angle()) * (g.pitch_radius() - g.inner_radius());
    const double end = role == Role::kInner ? 0.0 : g.length();
    const double entrance = role == Role::kInner ? -g.length() : 0.0;
    EXPECT_NEAR(high, end + band, 1e-15);
    EXPECT_NEAR(low, entrance - band, 1e-15);
  }
}

TEST(HelicoidRenderMeshFrameTest, RefusesAGridOfOneFlank) {
  const PartSpec part = Part(Role::kInner);
  SurfaceGrid grid = HelicoidDiscretizer().Discretize(part, Resolution{8, 2});
  grid.columns = 1;
  grid.rows = 16;
  EXPECT_THROW(HelicoidRenderMesh(part, grid), UserError);
}

}  // namespace render_mesh_test
}  // namespace fitfeel::thread
