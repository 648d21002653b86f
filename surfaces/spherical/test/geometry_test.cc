#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/spherical/spherical_discretizer.h"
#include "surfaces/spherical/spherical_geometry.h"
#include "surfaces/spherical/spherical_surface.h"
#include "surfaces/spherical/test/test_parts.h"

namespace fitfeel::spherical {
namespace {

ConfigNode Node(const std::string& text) {
  return ConfigNode::Parse(text, "test.yaml", "parts.p.geometry");
}

TEST(SphericalGeometry, BandAreaIsTwoPiAB) {
  // A zone of a sphere symmetric about the equator, height B: 2 pi a B.
  for (const PartSpec& part : {test::Ball(), test::Socket()}) {
    const auto& g = GeometryOf(part);
    EXPECT_NEAR(g.nominal_area(), 2.0 * M_PI * g.radius() * g.width(), 1e-18);
    for (Resolution r : {Resolution{}, Resolution{3, 8}, Resolution{40, 90}}) {
      const SurfaceGrid grid = SphericalDiscretizer().Discretize(part, r);
      EXPECT_NEAR(grid.area.sum(), 2.0 * M_PI * g.radius() * g.width(), 1e-12 * g.nominal_area());
      // Cell centres lie on the sphere, normals are radial and unit.
      for (int k = 0; k < grid.size(); ++k) {
        EXPECT_NEAR(grid.centre.col(k).norm(), g.radius(), 1e-15);
        EXPECT_NEAR(grid.normal.col(k).norm(), 1.0, 1e-15);
      }
      EXPECT_NEAR(grid.row_position(0), -grid.row_position(grid.rows - 1), 1e-15);
    }
  }
  // Independent check of the band area by integrating the surface of revolution numerically:
  // dA = 2 pi rho(y) sqrt(1 + rho'(y)^2) dy with rho = sqrt(a^2 - y^2).
  const double a = 10e-3, B = 10e-3;
  double area = 0.0;
  const int steps = 20000;
  for (int s = 0; s < steps; ++s) {
    const double y = -B / 2 + (s + 0.5) * B / steps;
    const double rho = std::sqrt(a * a - y * y);
    const double slope = -y / rho;
    area += 2.0 * M_PI * rho * std::sqrt(1.0 + slope * slope) * B / steps;
  }
  EXPECT_NEAR(GeometryOf(test::Socket()).nominal_area(), area, 1e-9 * area);
}

TEST(SphericalGeometry, MeanAxisDistanceIsTheBandAverage) {
  // The part owns its geometry: keep it alive while the reference is used.
  const PartSpec socket = test::Socket();
  const auto& g = GeometryOf(socket);
  double sum = 0.0;
  const int steps = 100000;
  for (int s = 0; s < steps; ++s) {
    const double y = -g.width() / 2 + (s + 0.5) * g.width() / steps;
    sum += std::sqrt(g.radius() * g.radius() - y * y);
  }
  EXPECT_NEAR(g.mean_axis_distance(), sum / steps, 1e-12);
}

TEST(SphericalGeometry, ParsesAndRefusesAtTheKey) {
  const PartSpec ball = test::Ball();
  const PartSpec socket = test::Socket();
  auto g = ParseSphericalGeometry(socket, Node("{width: 12 mm, outer_diameter: 35 mm}"));
  EXPECT_DOUBLE_EQ(g->width(), 12e-3);
  EXPECT_DOUBLE_EQ(g->outer_diameter(), 35e-3);
  const auto expect_error = [](const PartSpec& p, const std::string& text, const std::string& key) {
    try {
      ParseSphericalGeometry(p, Node(text));
      ADD_FAILURE() << "accepted " << text;
    } catch (const ScenarioError& e) {
      EXPECT_NE(e.key_path().find(key), std::string::npos) << e.what();
    }
  };
  expect_error(ball, "{width: 19 mm}", "width");  // wider than 0.9 dk = 18 mm
  expect_error(ball, "{width: 12 mm, outer_diameter: 35 mm}", "outer_diameter");
  expect_error(socket, "{width: 12 mm}", "outer_diameter");
  expect_error(socket, "{width: 12 mm, outer_diameter: 19 mm}", "outer_diameter");
  // The inner ring's bore: optional on the ball, inside the band's edge (dk 20 mm, band 12 mm:
  // 2 sqrt(10^2 - 6^2) = 16 mm), not on the socket.
  EXPECT_DOUBLE_EQ(
      ParseSphericalGeometry(ball, Node("{width: 12 mm, bore_diameter: 15 mm}"))->bore_diameter(),
      15e-3);
  EXPECT_EQ(ParseSphericalGeometry(ball, Node("{width: 12 mm}"))->bore_diameter(), 0.0);
  expect_error(ball, "{width: 12 mm, bore_diameter: 16 mm}", "bore_diameter");
  expect_error(ball, "{width: 12 mm, bore_diameter: -1 mm}", "bore_diameter");
  expect_error(socket, "{width: 12 mm, outer_diameter: 35 mm, bore_diameter: 5 mm}",
               "bore_diameter");
}

TEST(SphericalGeometry, RefusesUnusableResolutions) {
  EXPECT_THROW(SphericalDiscretizer().Discretize(test::Ball(), Resolution{10, 7}), UserError);
  EXPECT_THROW(SphericalDiscretizer().Discretize(test::Ball(), Resolution{1, 12}), UserError);
}

}  // namespace
}  // namespace fitfeel::spherical

namespace fitfeel::spherical {
namespace {

TEST(SphericalSurface, CheckPairRefusesAnotherSphereOrANarrowBall) {
  const ConfigNode parts = ConfigNode::Parse(
      "{ball: {size: 20 mm h7, geometry: {width: 8 mm}}, socket: "
      "{size: 22 mm H7, geometry: {width: 10 mm, outer_diameter: "
      "30 mm}}}",
      "test.yaml", "parts");
  const SphericalSurface surface;
  EXPECT_TRUE(surface.rotational());
  EXPECT_NO_THROW(surface.CheckPair(test::Ball(), test::Socket(), parts));
  try {
    surface.CheckPair(test::Ball(8e-3), test::Socket(), parts);
    ADD_FAILURE() << "accepted a ball band narrower than the socket's";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.key_path(), "parts.ball.geometry.width") << e.what();
  }
  PartSpec bigger = test::Socket();
  bigger.size.nominal = 22e-3;
  try {
    surface.CheckPair(test::Ball(), bigger, parts);
    ADD_FAILURE() << "accepted a 22 mm socket for a 20 mm ball";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.key_path(), "parts.socket.size") << e.what();
  }
}

}  // namespace
}  // namespace fitfeel::spherical
