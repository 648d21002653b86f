// The thread stub: closed-form flank area, flank normals, parameter validation, generated
// deviations recovered by the evaluation, and refusals that never pretend to render forces.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "surfaces/thread/thread_geometry.h"
#include "surfaces/thread/thread_shape.h"
#include "surfaces/thread/thread_surface.h"

namespace fitfeel::thread {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// M10 x 1.5 (ISO 261), 60 deg (ISO 68-1), 15 mm engaged; 6g pitch diameter limits.
PartSpec Bolt(double pitch_error = 0.0, double angle_error = 0.0) {
  PartSpec p;
  p.name = "bolt";
  p.role = Role::kInner;
  p.size = {10e-3, -144e-6, -32e-6, ""};
  p.material = {"steel", 210e9, 0.3};
  p.form.declared = {{"pitch_error", pitch_error}, {"flank_angle_error", angle_error}};
  p.geometry = std::make_shared<HelicoidGeometry>(Role::kInner, 10e-3, 1.5e-3, 60 * kDeg, 15e-3);
  return p;
}

TEST(HelicoidGeometryTest, FlankAreaOfM10ClosedFormAndGrid) {
  const PartSpec bolt = Bolt();
  const auto& g = HelicoidGeometryOf(bolt);
  // H = 1.5 / (2 tan 30 deg) = 1.29904 mm; r1 = 5 - 5H/8 = 4.18810 mm; 10 turns.
  EXPECT_NEAR(g.triangle_height(), 1.299038e-3, 1e-9);
  EXPECT_NEAR(g.inner_radius(), 4.188101e-3, 1e-9);
  EXPECT_NEAR(g.pitch_radius() * 2, 9.026e-3, 1e-6);  // ISO 724: d2 = d - 0.6495 P = 9.026 mm
  // Hand value (midpoint rule with 1e5 radii gives the same to 1e-12 relative): 270.8865 mm^2
  // per flank. The annulus over cos(30 deg) ignores the helix lead and gives 270.6119 mm^2.
  EXPECT_NEAR(g.flank_area(), 270.8865e-6, 0.0001e-6);
  EXPECT_NEAR(g.nominal_area(), 2 * 270.8865e-6, 0.0002e-6);
  const SurfaceGrid grid = HelicoidDiscretizer().Discretize(bolt, Resolution{});
  EXPECT_EQ(grid.rows, 160);
  EXPECT_EQ(grid.columns, 8);
  EXPECT_NEAR(grid.area.sum(), g.nominal_area(), 1e-12 * g.nominal_area());
  const SurfaceGrid coarse = HelicoidDiscretizer().Discretize(bolt, Resolution{7, 2});
  EXPECT_NEAR(coarse.area.sum(), g.nominal_area(), 1e-12 * g.nominal_area());
  EXPECT_THROW(HelicoidDiscretizer().Discretize(bolt, Resolution{7, 3}), UserError);
}

TEST(HelicoidGeometryTest, NormalsAreUnitAndNormalToTheHelicoid) {
  const PartSpec bolt = Bolt();
  const auto& g = HelicoidGeometryOf(bolt);
  const SurfaceGrid grid = HelicoidDiscretizer().Discretize(bolt, Resolution{40, 4});
  const double k = std::tan(g.half_angle()), c = g.pitch() / (2 * std::numbers::pi);
  for (int cell = 0; cell < grid.size(); ++cell) {
    const Eigen::Vector3d n = grid.normal.col(cell);
    const Eigen::Vector3d p = grid.centre.col(cell);
    const double s = cell % grid.columns < grid.columns / 2 ? 1.0 : -1.0;
    // A right-hand helix about +y: (r cos theta, c theta, -r sin theta).
    const double r = std::hypot(p.x(), p.z()), theta = std::atan2(-p.z(), p.x());
    // Tangents: d/dr = (cos, -s k, -sin); d/dtheta = (-r sin, c, -r cos) in (x, y, z).
    const Eigen::Vector3d tr(std::cos(theta), -s * k, -std::sin(theta));
    const Eigen::Vector3d tt(-r * std::sin(theta), c, -r * std::cos(theta));
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_NEAR(n.dot(tr), 0.0, 1e-12);
    EXPECT_NEAR(n.dot(tt) / r, 0.0, 1e-12);
    EXPECT_GT(n.y() * s, 0.0);  // flank A faces +y, flank B -y
  }
}

ConfigNode Node(const std::string& yaml) {
  return ConfigNode::Parse(yaml, "thread.yaml", "parts.bolt.geometry");
}

TEST(HelicoidGeometryTest, ParsesUnitsAndRefusesWhatNoThreadIs) {
  const PartSpec bolt = Bolt(5e-6, 0.01);
  const auto g = ParseHelicoidGeometry(
      bolt, Node("{nominal_diameter: 10 mm, pitch: 1.5 mm, flank_angle: 60 deg, length: 15 mm}"));
  EXPECT_DOUBLE_EQ(g->pitch(), 1.5e-3);
  EXPECT_DOUBLE_EQ(g->flank_angle(), 60 * kDeg);
  const std::string ok_rest = "length: 15 mm}";
  for (const std::string& bad : std::vector<std::string>{
           "{pitch: 1.5, flank_angle: 60 deg, " + ok_rest,        // no unit
           "{pitch: 4 mm, flank_angle: 60 deg, " + ok_rest,       // pitch above d/3
           "{pitch: 1.5 mm, flank_angle: 60, " + ok_rest,         // no unit on the angle
           "{pitch: 1.5 mm, flank_angle: 150 deg, " + ok_rest,    // no such thread
           "{pitch: 1.5 mm, flank_angle: 60 deg, length: 1 mm}",  // less than a turn
           "{pitch: 1.5 mm, flank_angle: 60 deg, length: 15 mm, lead: 3 mm}",         // unknown key
           "{pitch: 1.5 mm, flank_angle: 60 deg, length: 15 mm, pitch_error: 5 um}",  // form's
           "{nominal_diameter: 12 mm, pitch: 1.5 mm, flank_angle: 60 deg, " + ok_rest,
           "{pitch: 1.5 mm, flank_angle: 60 deg}",  // no length
       }) {
    EXPECT_THROW(ParseHelicoidGeometry(bolt, Node(bad)), ScenarioError) << bad;
  }
  // A pitch deviation above a tenth of the pitch is another thread: refused at the pitch.
  try {
    ParseHelicoidGeometry(Bolt(0.2e-3), Node("{pitch: 1.5 mm, flank_angle: 60 deg, " + ok_rest));
    ADD_FAILURE() << "a 0.2 mm pitch deviation of a 1.5 mm pitch was accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("parts.bolt.geometry.pitch"), std::string::npos)
        << e.what();
  }
}

TEST(HelicoidGeneratorTest, DeviationsStayInTheirLimitsAndUseThem) {
  const PartSpec bolt = Bolt(8e-6, 0.5 * kDeg);
  const SurfaceGrid grid = HelicoidDiscretizer().Discretize(bolt, Resolution{});
  double largest_pitch = 0.0, largest_angle = 0.0;
  for (int seed = 1; seed <= 200; ++seed) {
    Rng rng(seed);
    const SkinModelShape sms =
        HelicoidVariationGenerator().Generate(bolt, grid, TextureMode::kExpected, rng);
    for (const auto& check : EvaluateHelicoidCharacteristics(bolt, sms)) {
      EXPECT_TRUE(check.pass()) << seed << " " << check.name << " " << check.value;
      if (check.name == "pitch_deviation") {
        largest_pitch = std::max(largest_pitch, std::abs(check.value));
      }
      if (check.name == "flank_angle_deviation_a") {
        largest_angle = std::max(largest_angle, std::abs(check.value) / check.upper);
      }
    }
  }
  EXPECT_GT(largest_pitch, 0.9 * 8e-6);
  EXPECT_GT(largest_angle, 0.9);
}

TEST(HelicoidGeneratorTest, EvaluationRecoversKnownDeviations) {
  // V written from the geometry by hand: d2 + 40 um, pitch + 3 um, flank A +0.2 deg, B -0.3 deg.
  const PartSpec bolt = Bolt(8e-6, 0.5 * kDeg);
  const auto& g = HelicoidGeometryOf(bolt);
  SkinModelShape sms;
  sms.grid = HelicoidDiscretizer().Discretize(bolt, Resolution{64, 6});
  sms.variation.resize(sms.grid.size());
  const double beta = 30 * kDeg, c = 1.5e-3 / (2 * std::numbers::pi);
  for (int cell = 0; cell < sms.grid.size(); ++cell) {
    const int i = cell / sms.grid.columns, j = cell % sms.grid.columns;
    const double s = j < 3 ? 1.0 : -1.0;
    const double theta = sms.grid.row_position[i] / c;
    const double r = std::hypot(sms.grid.centre(0, cell), sms.grid.centre(2, cell));
    const double turn = s > 0 ? 0.2 * kDeg : -0.3 * kDeg;
    sms.variation[cell] =
        20e-6 * std::sin(beta) + s * 3e-6 * theta / (2 * std::numbers::pi) * std::cos(beta) -
        (std::tan(beta + turn) - std::tan(beta)) * std::cos(beta) * (r - g.pitch_radius());
  }
  const auto checks = EvaluateHelicoidCharacteristics(bolt, sms);
  ASSERT_EQ(checks.size(), 4u);
  EXPECT_NEAR(checks[0].value, 2 * g.pitch_radius() + 40e-6, 1e-12);
  EXPECT_NEAR(checks[1].value, 3e-6, 1e-12);
  // Across the flank height r2 - r1 = 5H/8 = 0.811899 mm.
  const double height = 5.0 / 8.0 * g.triangle_height();
  auto across = [&](double d) {
    return -(std::tan(beta + d) - std::tan(beta)) * std::cos(beta) * height;
  };
  EXPECT_NEAR(checks[2].value, across(0.2 * kDeg), 1e-15);
  EXPECT_NEAR(checks[3].value, across(-0.3 * kDeg), 1e-15);
  EXPECT_TRUE(checks[2].pass());
  EXPECT_TRUE(checks[3].pass());

  EXPECT_FALSE(checks[0].pass());  // +40 um is outside 6g
}

TEST(ThreadSurfaceTest, OffersTheFlankLawAndAScrewGeometry) {
  const ThreadSurface surface;
  EXPECT_TRUE(surface.renders_forces());
  EXPECT_EQ(surface.law_names(), std::vector<std::string>{"flank"});
  EXPECT_THROW(surface.MakeLaw("gps"), UserError);
  EXPECT_DOUBLE_EQ(HelicoidGeometryOf(Bolt()).lead(), 1.5e-3);
}

}  // namespace
}  // namespace fitfeel::thread
