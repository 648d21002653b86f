// A hand assembles the parts: the simulated hand (0.5 kg held by 2000 N/m and
// 20 N*s/m to its target, physiological tremor 0.1 mm at 10 Hz) aims 0.3 mm or 1 mm off the axis
// and pushes each shipped scenario's moving part (shafts, pins, the taper pin, the key, the
// square shaft) along a line parallel to the axis, 27 mm in 3 s. The chamfers guide the part (the
// positioning stage's god object), the constrained stage takes it over where the lead-in ends, and
// the hand feels the part through a spring no stiffer than it can render (2 b / T). Fits a handbook
// joins by hand go in to full engagement; fits it joins with a mallet or a press stop the hand at
// their onset. Either way the hand meets no force beyond what it pushes with and no energy is
// created.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/plugin/registry.h"
#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/run.h"
#include "framework/scenario/scene.h"
#include "framework/testing/build_tree_plugins.h"
#include "framework/testing/cli_runner.h"
#include "framework/testing/hand_scene.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

using test_support::kHandPushIn;
using test_support::kHandStiffness;
using test_support::kHandTremor;
constexpr double kStroke = 27e-3;  // m, how far the hand's target travels (kHandPushIn)

// How a handbook joins the fit (sliding / by hand; light mallet; press).
enum class Joining { kByHand, kNotByHand };

struct HandCase {
  std::string scenario;
  Joining joining;
};

void PrintTo(const HandCase& c, std::ostream* out) { *out << c.scenario; }

// The shipped scenario with the hand as its device (moving the part named `moving`, where not
// empty, instead of the scenario's own), written beside the test's outputs.
fs::path WithHand(const std::string& scenario, double aim, const std::string& waypoints,
                  double seconds, const fs::path& dir, const std::string& moving) {
  std::string text =
      test_support::ReadText(fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / scenario);
  if (!moving.empty()) text = test_support::WithMoving(text, moving);
  const fs::path file =
      dir / ("hand-" + std::to_string(static_cast<int>(aim * 1e6)) + "um-" + scenario);
  std::ofstream(file) << test_support::WithHand(text, aim, waypoints, seconds);
  return file;
}

RunResult RunHand(const std::string& scenario, double aim, const std::string& waypoints,
                  double seconds, const fs::path& out = {}, const std::string& moving = "") {
  // A folder of its own per role: tests of both roles on one scenario may run at once.
  const fs::path dir =
      test_support::EmptyFolder("hand-insertion", (moving.empty() ? "" : "outer-") + scenario);
  Scene scene = LoadScene(WithHand(scenario, aim, waypoints, seconds, dir, moving),
                          test_support::BuildTreePlugins());
  RunOptions options;
  options.out_dir = out;
  return RunScene(std::move(scene), options);
}

// The stages a run's trace went through, three letters of each, in order, with the header's
// "sta" first: "staposconpos" for free, captured, released.
std::string StageSequence(const fs::path& trace_csv) {
  std::ifstream trace(trace_csv);
  std::string line, stages;
  while (std::getline(trace, line)) {
    const std::string stage = line.substr(line.find(',') + 1, 3);
    if (stages.empty() || stages.substr(stages.size() - 3) != stage) stages += stage;
  }
  return stages;
}

// A scenario file's name as a test name: its stem, dashes to underscores.
std::string TestName(const std::string& file) {
  std::string name = file.substr(0, file.find('.'));
  for (char& ch : name) {
    if (ch == '-') ch = '_';
  }
  return name;
}

class HandInsertion : public ::testing::TestWithParam<HandCase> {};

TEST_P(HandInsertion, OffTheAxisWithTremor) {
  const HandCase& c = GetParam();
  for (const double aim : {0.3e-3, 1e-3}) {
    SCOPED_TRACE(std::to_string(aim * 1e3) + " mm off the axis");
    const RunResult result = RunHand(c.scenario, aim, kHandPushIn, 3.5);
    const nlohmann::json& s = result.summary;
    const double ticks = s["ticks"].get<double>();
    const double constrained = s["constrained_ticks"].get<double>();
    const double deepest = s["depth_mm"]["max"].get<double>() * 1e-3;
    const double largest = s["safety"]["max_delivered_force_N"].get<double>();
    // Nothing the hand holds gains energy from the rendering (the passivity observer's count).
    EXPECT_LE(s["safety"]["energy_created_J"].get<double>(), 1e-9);
    // The hand meets no force beyond the strongest push its spring gives over the stroke.
    EXPECT_LE(largest, kHandStiffness * kStroke);
    // The part was caught and handed over by the lead-in.
    EXPECT_GT(constrained, 0.0);
    if (c.joining == Joining::kByHand) {
      // In to 20 mm: the whole length of every bore here (more than half the keyway's), most of
      // the run in contact.
      EXPECT_GE(deepest, 20e-3);
      EXPECT_GE(constrained, 0.8 * ticks);
    } else {
      // Stopped by the press's onset within the first couple of millimetres.
      EXPECT_LE(deepest, 2e-3);
    }
  }
}

// A clearance fit carries only what the hand presses sideways, (aim + 2 tremor) times its
// stiffness, and the friction on that: twice the pull bounds both, the hand's own inertia too.
// Its old failure was kN.
TEST(HandInsertionClearance, TheHandFeelsItsOwnPullNotTheWall) {
  for (const char* scenario : {"paper-case1-h7g6.yaml", "fits-20mm-h7h6.yaml"}) {
    for (const double aim : {0.3e-3, 1e-3}) {
      SCOPED_TRACE(std::string(scenario) + ", " + std::to_string(aim * 1e3) + " mm off");
      const RunResult result = RunHand(scenario, aim, kHandPushIn, 3.5);
      EXPECT_LE(result.summary["safety"]["max_delivered_force_N"].get<double>(),
                2.0 * kHandStiffness * (aim + 2.0 * kHandTremor));
    }
  }
}

// The robot's press fit rendered as a Touch would render it (device `model: touch`): the safety
// chain's coupling and limits hold every delivered force at the Touch's 3.3 N peak, with no energy
// created, and summary.json says what was delivered beside the scene's forces.
TEST(DeviceModel, APressFitRenderedAsATouchStaysWithinItsPeak) {
  std::string text = test_support::ReadText(test_support::ShippedScenario("fits-20mm-h7k6.yaml"));
  const std::string robot = "  speed: 10 mm/s           # paper 4.1\n";
  ASSERT_NE(text.find(robot), std::string::npos);
  text.replace(text.find(robot), robot.size(), robot + "  model: touch\n");
  const RunResult result = RunScene(
      LoadSceneFromYaml(text, "touch.yaml", test_support::BuildTreePlugins()), RunOptions{});
  const nlohmann::json& delivered = result.summary["delivered_force_N"];
  EXPECT_LE(delivered["max"].get<double>(), 3.3 + 1e-9);
  EXPECT_GT(delivered["mean"].get<double>(), 1.0);  // the press fit is felt, saturated
  EXPECT_GT(result.summary["safety"]["peak_limited_ticks"].get<int>(), 0);
  EXPECT_EQ(result.summary["safety"]["energy_created_J"].get<double>(), 0.0);
  EXPECT_NE(result.summary["safety"]["device_model"].get<std::string>().find("as Touch"),
            std::string::npos);
}

// In and out again: released to free motion past the entrance, no energy created on the way.
TEST(HandInsertionRelease, PulledOutTheConstrainedStageLetsGo) {
  const fs::path out = test_support::EmptyFolder("hand-insertion", "release") / "run";
  const RunResult result = RunHand(
      "paper-case1-h7g6.yaml", 1e-3,
      std::string(kHandPushIn) + "    - {time: 5 s, position: [0 mm, -5 mm, 0 mm]}\n", 6.0, out);
  EXPECT_LE(result.summary["safety"]["energy_created_J"].get<double>(), 1e-9);
  EXPECT_LE(result.summary["safety"]["max_delivered_force_N"].get<double>(),
            2.0 * kHandStiffness * (1e-3 + 2.0 * kHandTremor));
  // Free, captured, released: positioning, constrained, positioning.
  EXPECT_EQ(StageSequence(out / "trace.csv"), "staposconpos")
      << "stage sequence (3 letters each, header first)";
}

// The taper pin wedged with the hand's target millimetres ahead: the god object balances the part
// across the axis at the device's depth and at its own every tick (GodObject's AcrossMemory,
// one memory each), each on the cone's smooth Winkler wall. The searches along lines from the
// device take false position from a bracket both of whose ends the wall pushes (measured, contact
// evaluations per tick p50 / p99 / max: 12 / 31 / 34 with one memory and the wall's Newton step,
// 12 / 28 / 41 with two memories, 10 / 23 / 37 with both changes); Newton's method in both
// directions from the last balance, on the cone's stiffness in closed form
// (ResistanceLaw::RadialJacobian), takes 7 / 11 / 33.
TEST(HandInsertionWedged, TheGodObjectsBalancesStartFromTheirOwnLastRoots) {
  const RunResult result = RunHand("taper-pin.yaml", 1e-3, kHandPushIn, 3.5);
  const nlohmann::json& e = result.summary["contact_evaluations"];
  EXPECT_LE(e["p50"].get<double>(), 7.0);
  EXPECT_LE(e["p99"].get<double>(), 12.0);
}

// The robot presses the taper pin home with its weight across the axis: the settle steps on the
// cone's stiffness in closed form (ResistanceLaw::RadialJacobian) from the first evaluation,
// instead of a search along the load and secant-corrected steps (measured, contact evaluations
// per tick p50 / p99 / max: 2 / 5 / 25 with it, 2 / 6 / 29 without; the pressing phase's ticks
// 2-3, not 4-5).
TEST(RobotPressesTheTaperPin, TheSettleStepsOnTheClosedFormStiffness) {
  const PluginRegistry& registry = test_support::BuildTreePlugins();
  Scene scene =
      LoadScene(fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / "taper-pin.yaml", registry);
  const RunResult result = RunScene(std::move(scene), RunOptions{});
  const nlohmann::json& e = result.summary["contact_evaluations"];
  EXPECT_LE(e["p50"].get<double>(), 2.0);
  EXPECT_LE(e["p99"].get<double>(), 5.0);
}

// The paper's H7/g6 by hand 1 mm off: the god object's balance on the line from the assembly
// space's edge to the hand takes the secant of its two probes on the wall (measured, contact
// evaluations per tick p50 / p99 / max: 14 / 26 / 34 with the carried slope's Newton step and a
// wall probe, 13 / 26 / 34 with the secant).
TEST(HandInsertionClearance, TheGodObjectsLineTakesTheWallsSecant) {
  const RunResult result = RunHand("paper-case1-h7g6.yaml", 1e-3, kHandPushIn, 3.5);
  const nlohmann::json& e = result.summary["contact_evaluations"];
  EXPECT_LE(e["p50"].get<double>(), 13.0);
  EXPECT_LE(e["p99"].get<double>(), 26.0);
}

// The hand holds the outer part and slides it onto the fixed inner one, 1 mm off the axis, and
// back off: the lead-in guides it as it guides a moving inner part (docs/lead-in.md; FCL was
// this case's only path before, 0.4-0.5 ms a tick in contact), the constrained stage takes it
// over, the fits a hand joins go on to full engagement, and pulled back the part is released.
struct OuterCase {
  std::string scenario;
  std::string outer;  // the outer part's name in the scenario
};

void PrintTo(const OuterCase& c, std::ostream* out) { *out << c.scenario; }

class HandSlidesTheOuterPart : public ::testing::TestWithParam<OuterCase> {};

TEST_P(HandSlidesTheOuterPart, OnAndOffAgain) {
  const OuterCase& c = GetParam();
  const fs::path out =
      test_support::EmptyFolder("hand-insertion", "outer-run-" + c.scenario) / "run";
  const RunResult result =
      RunHand(c.scenario, 1e-3,
              std::string(kHandPushIn) + "    - {time: 5 s, position: [0 mm, -5 mm, 0 mm]}\n", 6.0,
              out, c.outer);
  const nlohmann::json& s = result.summary;
  EXPECT_LE(s["safety"]["energy_created_J"].get<double>(), 1e-9);
  EXPECT_LE(s["safety"]["max_delivered_force_N"].get<double>(),
            2.0 * kHandStiffness * (1e-3 + 2.0 * kHandTremor));
  EXPECT_GE(s["depth_mm"]["max"].get<double>(), 20.0);
  EXPECT_GE(s["constrained_ticks"].get<double>(), 0.6 * s["ticks"].get<double>());
  EXPECT_EQ(StageSequence(out / "trace.csv"), "staposconpos")
      << "stage sequence (3 letters each, header first)";
}

// With the outer part moving the constrained stage meets the inner part in the outer part's frame,
// the scene's reflected in z (AnalyzerPose): on the paper's H7/g6 parts (skin model shapes with
// form, so that the reflection matters) a stage told the bushing moves answers the device at
// (x, y, z) with the reflection of what a stage told the shaft moves answers at (x, y, -z), bit
// for bit, tick after tick of a path across the bore with a load pulling along z, held rigidly
// (settled under the load) and through the god object's spring. Without the reflection the
// bushing met its own drawn bore upside down.
TEST(OuterPartMoving, TheStageMeetsTheInnerPartInTheOuterPartsFrame) {
  const Scene scene =
      LoadScene(fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / "paper-case1-h7g6.yaml",
                test_support::BuildTreePlugins());
  const PreparedScene prepared = Prepare(scene);
  const Eigen::Vector3d reflect(1.0, 1.0, -1.0);
  for (const double spring : {std::numeric_limits<double>::infinity(), 2e3}) {
    ConstrainedStage::Options inner_options, outer_options;
    inner_options.proxy_stiffness = outer_options.proxy_stiffness = spring;
    outer_options.moving = Role::kOuter;
    const ConstrainedStage inner(*prepared.analyzer, *prepared.law, inner_options);
    const ConstrainedStage outer(*prepared.analyzer, *prepared.law, outer_options);
    const auto inner_run = inner.MakeState(), outer_run = outer.MakeState();
    StageOutput a, b;
    for (int i = 0; i < 400; ++i) {
      SCOPED_TRACE("tick " + std::to_string(i) + ", spring " + std::to_string(spring));
      PartState device;
      device.position =
          Eigen::Vector3d(20e-6 * std::sin(0.05 * i), 1e-3 + 20e-6 * i, 30e-6 * std::cos(0.03 * i));
      device.velocity = Eigen::Vector3d(1e-3, 10e-3, -2e-3);
      // The robot lets 2 N act on the part (settled); the god object's spring carries it.
      if (std::isinf(spring)) device.settle_load = Eigen::Vector2d(0.3, -2.0);
      PartState reflected = device;
      reflected.position = device.position.cwiseProduct(reflect);
      reflected.velocity = device.velocity.cwiseProduct(reflect);
      reflected.settle_load.y() = -device.settle_load.y();
      inner.Evaluate(reflected, inner_run.get(), &a);
      outer.Evaluate(device, outer_run.get(), &b);
      ASSERT_EQ(b.wrench.force, a.wrench.force.cwiseProduct(reflect));
      ASSERT_EQ(b.pose.offset, Eigen::Vector2d(a.pose.offset.x(), -a.pose.offset.y()));
      ASSERT_EQ(b.pose.depth, a.pose.depth);
      ASSERT_EQ(b.contact.penetration_direction.y(), -a.contact.penetration_direction.y());
      ASSERT_EQ(b.contact.normal_force, a.contact.normal_force);
    }
    // The path meets the bore's wall: the comparison saw forces.
    EXPECT_GT(b.wrench.force.norm(), 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Shipped, HandSlidesTheOuterPart,
                         ::testing::Values(OuterCase{"paper-case1-h7g6.yaml", "bushing"},
                                           OuterCase{"fits-20mm-h7js6.yaml", "bushing"},
                                           OuterCase{"taper-pin.yaml", "hub"},
                                           OuterCase{"key-parallel.yaml", "hub_keyway"},
                                           OuterCase{"square-shaft.yaml", "hub"}),
                         [](const auto& param_info) {
                           return TestName(param_info.param.scenario);
                         });

INSTANTIATE_TEST_SUITE_P(
    Shipped, HandInsertion,
    ::testing::Values(HandCase{"paper-case1-h7g6.yaml", Joining::kByHand},
                      HandCase{"paper-case1-h7js6.yaml", Joining::kByHand},
                      HandCase{"fits-20mm-h7g6.yaml", Joining::kByHand},
                      HandCase{"fits-20mm-h7h6.yaml", Joining::kByHand},
                      HandCase{"fits-20mm-h7js6.yaml", Joining::kByHand},
                      HandCase{"fits-20mm-h7k6.yaml", Joining::kNotByHand},
                      HandCase{"fits-20mm-h7n6.yaml", Joining::kNotByHand},
                      HandCase{"fits-20mm-h7p6.yaml", Joining::kNotByHand},
                      HandCase{"fits-20mm-h7s6.yaml", Joining::kNotByHand},
                      HandCase{"pin-cylindrical.yaml", Joining::kNotByHand},
                      // A taper pin goes in by hand until the cones wedge (at the middle of their
                      // size zones 20 + 0.058 mm / (1:50) = 22.9 mm), then a hammer drives it.
                      HandCase{"taper-pin.yaml", Joining::kByHand},
                      // A DIN 6885 key slides into its JS9 hub keyway by hand; so does the square.
                      HandCase{"key-parallel.yaml", Joining::kByHand},
                      HandCase{"square-shaft.yaml", Joining::kByHand}),
    [](const auto& param_info) { return TestName(param_info.param.scenario); });

}  // namespace
}  // namespace fitfeel
