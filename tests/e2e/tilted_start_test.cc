// A shaft held tilted by a rigid robot against the geometry of peg-in-hole (Whitney, ASME J. Dyn.
// Sys. Meas. Control 104:65, 1982; docs/tilted-parts.md): a rigid peg of diameter d tilted by
// theta in a bore of diameter D touches at two points once its leading edge is
// l = (D - d cos theta) / sin theta past the entrance, and can wedge where that happens with
// l / D < mu, which for small tilts is theta > c / mu (clearance ratio c = (D - d) / D).

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/runtime/run.h"
#include "framework/scenario/scene.h"
#include "framework/testing/build_tree_plugins.h"
#include "framework/testing/cli_runner.h"

namespace fitfeel {
namespace {

constexpr double kBore = 20e-3;   // m
constexpr double kSpeed = 10e-3;  // m/s, the robot's

double Degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

// The geometry's two-point depth (Whitney's l), m.
double TwoPointDepth(double tilt, double clearance) {
  return (kBore - (kBore - clearance) * std::cos(tilt)) / std::sin(tilt);
}

// A form-free shaft and bore with `clearance` on the diameter (each size drawn within a
// nanometre), the robot holding the shaft at `tilt` about x, pushed past where the geometry
// puts two-point contact; the summary of the run.
nlohmann::json RunTilted(double tilt, double clearance) {
  const double expected = TwoPointDepth(tilt, clearance);
  // 250 steps to the expected depth (0.4 % of it); the run goes 30 % past it.
  const double step = expected / 250.0;
  const double seconds = std::min(1.3 * expected, 19e-3) / kSpeed + 0.1;
  std::ostringstream yaml;
  yaml.precision(12);
  yaml << "scenario: tilted-start\n"
       << "surface: fitfeel.surface.cylindrical\n"
       << "parts:\n"
       << "  shaft:\n"
       << "    role: inner\n"
       << "    size: {nominal: 20 mm, lower: " << -clearance * 1e6 - 0.001
       << " um, upper: " << -clearance * 1e6 + 0.001 << " um}\n"
       << "    geometry: {length: 30 mm}\n"
       << "    material: {name: steel, youngs_modulus: 210 GPa, poisson: 0.3}\n"
       << "  bushing:\n"
       << "    role: outer\n"
       << "    size: {nominal: 20 mm, lower: -0.001 um, upper: 0.001 um}\n"
       << "    geometry: {length: 20 mm, outer_diameter: 30 mm}\n"
       << "    material: {name: steel, youngs_modulus: 210 GPa, poisson: 0.3}\n"
       << "moving: shaft\n"
       << "model:\n"
       << "  law: gps\n"
       << "  friction: 0.15\n"
       << "  contact_stiffness: 3665 N/um\n"
       << "  resolution: {rows: 300, columns: 72}\n"
       << "  depth_step: " << step * 1e3 << " mm\n"
       << "part_motion:\n"
       << "  radial_load: 2 N\n"
       << "device:\n"
       << "  plugin: fitfeel.device.simulated\n"
       << "  speed: 10 mm/s\n"
       << "  tilt: [" << Degrees(tilt) << " deg, 0 deg]\n"
       << "run:\n"
       << "  rate: 1000 Hz\n"
       << "  duration: " << seconds << " s\n"
       << "  seed: 1\n"
       << "  clock: virtual\n"
       << "  outputs: []\n";
  Scene scene =
      LoadSceneFromYaml(yaml.str(), "tilted-start.yaml", test_support::BuildTreePlugins());
  return RunScene(std::move(scene), RunOptions{}).summary;
}

// Rigid shaft at 0.1, 0.2 and 0.5 degrees into a form-free bore with 20 um diametral clearance:
// two-point contact begins within 5 % of the geometry's depth, and from there the robot presses
// the parts into each other: the resistance rises far above the sliding friction of the weight.
TEST(TiltedStart, TwoPointContactAtTheGeometrysDepth) {
  for (const double degrees : {0.1, 0.2, 0.5}) {
    SCOPED_TRACE(std::to_string(degrees) + " deg");
    const double tilt = degrees * std::numbers::pi / 180.0;
    const nlohmann::json s = RunTilted(tilt, 20e-6);
    ASSERT_TRUE(s["two_point_contact_depth_mm"].is_number());
    const double depth = s["two_point_contact_depth_mm"].get<double>() * 1e-3;
    const double expected = TwoPointDepth(tilt, 20e-6);
    std::cout << degrees << " deg: two-point contact at " << depth * 1e3 << " mm, geometry "
              << expected * 1e3 << " mm\n";
    EXPECT_NEAR(depth, expected, 0.05 * expected);
    EXPECT_NEAR(s["held_tilt_deg"].get<double>(), degrees, 1e-9);
    // Before, the shaft slides on its weight: 0.15 x 2 N. Pressed at two points it resists more
    // than ten times that within 30 % more travel.
    EXPECT_GT(s["axial_resistance_N"]["max"].get<double>(), 3.0);
  }
}

// An aligned part never touches at two points: the key is null.
TEST(TiltedStart, AlignedPartHasNoTwoPointContact) {
  Scene scene = LoadScene(
      std::filesystem::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / "paper-case1-h7g6.yaml",
      test_support::BuildTreePlugins());
  scene.run.duration = 0.5;
  EXPECT_TRUE(
      RunScene(std::move(scene), RunOptions{}).summary["two_point_contact_depth_mm"].is_null());
}

// A tilt the model cannot take is refused before anything runs: the elastic law solves the part's
// own tilt.
TEST(TiltedStart, ElasticLawRefusesAHeldTilt) {
  std::string text = test_support::ReadText(std::filesystem::path(FITFEEL_TEST_SOURCE_DIR) /
                                            "scenarios" / "paper-case1-h7g6.yaml");
  const std::string speed = "speed: 10 mm/s";
  text.replace(text.find(speed), speed.size(), speed + "\n  tilt: [0.2 deg, 0 deg]");
  Scene scene = LoadSceneFromYaml(text, "tilted.yaml", test_support::BuildTreePlugins());
  try {
    RunScene(std::move(scene), RunOptions{});
    ADD_FAILURE() << "a held tilt with law elastic ran";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("law 'elastic'"), std::string::npos) << e.what();
  }
}

// Whitney's wedging condition over a sweep of tilt, clearance ratio and friction: the run's own
// two-point depth l (null where the part reaches no two-point contact within the 20 mm bore) says
// the start can wedge when l / D < mu (the line between the two contacts lies inside both friction
// cones); the closed form says theta > c / mu. They agree everywhere off a 5 % band around the
// boundary.
TEST(TiltedStart, WedgingAgreesWithWhitneysCondition) {
  int compared = 0, near_boundary = 0, wedging = 0;
  for (const double ratio : {0.5e-3, 1e-3, 2e-3}) {
    for (const double degrees : {0.1, 0.2, 0.35, 0.6, 0.9}) {
      const double tilt = degrees * std::numbers::pi / 180.0;
      const nlohmann::json s = RunTilted(tilt, ratio * kBore);
      const bool touches = s["two_point_contact_depth_mm"].is_number();
      const double depth =
          touches ? s["two_point_contact_depth_mm"].get<double>() * 1e-3 : INFINITY;
      for (const double mu : {0.1, 0.15, 0.3}) {
        SCOPED_TRACE("c " + std::to_string(ratio) + ", " + std::to_string(degrees) + " deg, mu " +
                     std::to_string(mu));
        const double boundary = ratio / mu;
        if (std::abs(tilt - boundary) <= 0.05 * boundary) {
          ++near_boundary;
          continue;
        }
        const bool whitney = tilt > boundary;
        const bool simulated = depth / kBore < mu;
        EXPECT_EQ(simulated, whitney) << "two-point depth " << depth * 1e3 << " mm";
        ++compared;
        wedging += whitney ? 1 : 0;
      }
    }
  }
  std::cout << compared << " cases compared (" << wedging << " can wedge), " << near_boundary
            << " within 5 % of the boundary\n";
  // The sweep straddles the boundary: both outcomes occur.
  EXPECT_GT(wedging, 5);
  EXPECT_LT(wedging, compared - 5);
}

}  // namespace
}  // namespace fitfeel
