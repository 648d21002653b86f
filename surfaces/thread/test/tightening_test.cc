// A nut run down and tightened by the screw stage on the shipped bolt scene, against the
// independent analyses of docs/threads.md: the helicoid flank's and the bearing annulus's torque
// per unit preload, and VDI 2230's preload per turn.
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/runtime/prepare.h"
#include "framework/runtime/run.h"
#include "framework/runtime/scene_stages.h"
#include "framework/runtime/screw_stage.h"
#include "framework/scenario/scene.h"
#include "framework/testing/build_tree_plugins.h"
#include "framework/testing/cli_runner.h"
#include "framework/testing/source_tree.h"
#include "surfaces/thread/bolted_joint.h"
#include "surfaces/thread/thread_geometry.h"
#include "surfaces/thread/thread_torque.h"

namespace fitfeel::thread {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// `text` with every `from` replaced by `to` (exactly one occurrence expected).
std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string BoltScene() {
  return test_support::ReadText(test_support::ShippedScenario("bolt-m10.yaml"));
}

// The bolt scene at friction mu (flanks and face) and pitch `pitch_mm`.
std::string WithFriction(double mu, const std::string& pitch_mm = "1.5") {
  std::string text = BoltScene();
  const std::string m = std::to_string(mu);
  text = Replaced(text, "friction: 0.12             # mu_G", "friction: " + m);
  text = Replaced(text, "bearing_friction: 0.12  # mu_K", "bearing_friction: " + m);
  text = Replaced(text, "M10x1.5 6g", "M10x" + pitch_mm + " 6g");
  text = Replaced(text, "M10x1.5 6H", "M10x" + pitch_mm + " 6H");
  return text;
}

struct Tick {
  double angle = 0.0;
  ScrewOutput screw;
};

// The screw stage driven by a robot at the scene's turning speed, tick by tick from the bolt's
// end, until its target or `seconds`.
std::vector<Tick> Tighten(const std::string& text, std::uint64_t seed, double seconds) {
  Scene scene = LoadSceneFromYaml(text, "bolt.yaml", test_support::BuildTreePlugins());
  scene.run.seed = seed;
  const PreparedScene prepared = Prepare(scene);
  DeviceSpec robot;
  robot.max_stiffness = std::numeric_limits<double>::infinity();
  const SceneStages stages = MakeSceneStages(scene, prepared, robot);
  EXPECT_NE(dynamic_cast<const ScrewStage*>(stages.constrained.get()), nullptr);
  const auto state = stages.constrained->MakeState();
  StageOutput out;
  out.stage = StageId::kPositioning;  // handed over at the bolt's end
  std::vector<Tick> ticks;
  const double period = 1.0 / scene.run.rate;
  for (int k = 0; k * period < seconds; ++k) {
    PartState part;
    part.time = k * period;
    stages.constrained->Evaluate(part, state.get(), &out);
    ticks.push_back({out.pose.angle, out.screw});
    if (out.screw.stopped) break;
  }
  return ticks;
}

TEST(Tightening, AZeroFormPairRunsDownFreely) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const std::vector<Tick> ticks = Tighten(BoltScene(), seed, 8.0);
    double largest = 0.0;
    for (const Tick& t : ticks) {
      if (!t.screw.seated) largest = std::max(largest, std::abs(t.screw.torque));
    }
    ASSERT_TRUE(ticks.back().screw.seated) << "seed " << seed;
    EXPECT_LT(largest, 0.05) << "seed " << seed;
    EXPECT_TRUE(ticks.back().screw.stopped) << "seed " << seed;
  }
}

TEST(Tightening, TorqueSharesMatchTheFlankAndAnnulusAnalyses) {
  for (const std::string pitch : {"1.5", "1.25"}) {
    for (const double mu : {0.08, 0.12, 0.16}) {
      SCOPED_TRACE("P " + pitch + " mm, mu " + std::to_string(mu));
      const std::string text = WithFriction(mu, pitch);
      const std::vector<Tick> ticks = Tighten(text, 1, 8.0);
      const ScrewOutput& end = ticks.back().screw;
      ASSERT_TRUE(end.stopped);
      // The analyses: the Winkler pressure over the flank band of the ISO 68-1 profile the
      // scene's parts have, and uniform pressure over the ISO 4032 nut's bearing annulus on the
      // ISO 273 medium hole (the joint's defaults).
      const double p = std::stod(pitch) * 1e-3;
      const HelicoidGeometry g(Role::kInner, 10e-3, p, 60.0 * kDegree, 35e-3);
      const TorqueRatio flank = HelicoidTorqueRatio(p, 60.0 * kDegree, g.inner_radius(),
                                                    g.outer_radius(), mu, FlankPressure::kWinkler);
      const double annulus = UniformAnnulusTorqueRatio(14.6e-3, 11e-3, mu);
      EXPECT_NEAR(end.thread_torque / end.preload / flank.total, 1.0, 0.02);
      EXPECT_NEAR(end.head_torque / end.preload / annulus, 1.0, 0.02);
    }
  }
}

// The same whether the flanks share the load evenly or in Sopwith's proportions (the nut's
// stiffness is the engaged thread's either way).
TEST(Tightening, PreloadRisesPerTurnAsTheJointsCompliancesSay) {
  for (const bool sopwith : {false, true}) {
    SCOPED_TRACE(sopwith ? "sopwith" : "uniform");
    const std::string text =
        sopwith ? Replaced(BoltScene(), "    joint:\n", "    distribution: sopwith\n    joint:\n")
                : BoltScene();
    const std::vector<Tick> ticks = Tighten(text, 1, 8.0);
    const double final_preload = ticks.back().screw.preload;
    ASSERT_GT(final_preload, 10e3);
    // The slope between 30 % and 90 % of the final preload, once the flanks' play is taken up.
    const Tick *a = nullptr, *b = nullptr;
    for (const Tick& t : ticks) {
      if (a == nullptr && t.screw.preload >= 0.3 * final_preload) a = &t;
      if (b == nullptr && t.screw.preload >= 0.9 * final_preload) b = &t;
    }
    ASSERT_TRUE(a != nullptr && b != nullptr && b->angle > a->angle);
    const double per_turn =
        (b->screw.preload - a->screw.preload) / (b->angle - a->angle) * 2.0 * std::numbers::pi;
    // VDI 2230: the fully threaded M10 x 35 through 20 mm of plates 40 mm wide, E = 205 GPa.
    const BoltResilience bolt = ThroughBoltResilience({10e-3, 1.5e-3, 20e-3, {}, 205e9, 205e9});
    const double plates =
        ThroughBoltPlateResilience({14.6e-3, 11e-3, 20e-3, 40e-3, 205e9}).resilience;
    EXPECT_NEAR(per_turn / PreloadPerTurn(1.5e-3, bolt.total(), plates), 1.0, 0.05);
  }
}

// Three turns on and off again by hand, the hand pulling back faster than the thread lets the nut
// go: the hand feels its coupling spring, never the flanks' stiffness, creates no energy, and the
// nut leaves the bolt.
TEST(Tightening, AHandUnscrewsTheNutPassively) {
  std::string text = test_support::ReadText(test_support::ShippedScenario("nut-by-hand.yaml"));
  const std::size_t from = text.find("  waypoints:\n"), to = text.find("run:");
  ASSERT_NE(from, std::string::npos);
  text.replace(from, to - from,
               "  waypoints:\n"
               "    - {time: 0 s, position: [0 mm, -1 mm, 0 mm], angle: 0 deg}\n"
               "    - {time: 0.5 s, position: [0 mm, 0.2 mm, 0 mm], angle: 0 deg}\n"
               "    - {time: 2.5 s, position: [0 mm, 4.7 mm, 0 mm], angle: 1080 deg}\n"
               "    - {time: 5 s, position: [0 mm, -3 mm, 0 mm], angle: -360 deg}\n");
  text = Replaced(text, "duration: 7.5 s", "duration: 5.5 s");
  const RunResult run = RunScene(
      LoadSceneFromYaml(text, "unscrew.yaml", test_support::BuildTreePlugins()), RunOptions{});
  EXPECT_EQ(run.summary["safety"]["energy_created_J"].get<double>(), 0.0);
  // The coupling's spring: a few newtons over the millimetre the hand leads or lags.
  EXPECT_LT(run.summary["axial_resistance_N"]["max"].get<double>(), 10.0);
  EXPECT_EQ(run.final_stage, StageId::kPositioning);
}

// What `fitfeel validate` says of the joint before a run: VDI 2230's numbers for this bolt.
TEST(Tightening, ValidateDescribesTheJointInVdiTerms) {
  const Scene scene = LoadSceneFromYaml(BoltScene(), "bolt.yaml", test_support::BuildTreePlugins());
  std::string text;
  for (const std::string& line :
       scene.surface->DescribeModel(scene.inner, scene.outer, scene.model)) {
    text += line + "\n";
  }
  EXPECT_NE(text.find("axial play 18.5 .. 198.6 um"), std::string::npos) << text;
  EXPECT_NE(text.find("preload 434.4 kN per turn past snug"), std::string::npos) << text;
  EXPECT_NE(text.find("1.64 N*m per kN"), std::string::npos) << text;
  EXPECT_NE(text.find("F_M,zul 29.6 kN"), std::string::npos) << text;
}

// Held crooked by the wrench: within the flanks' play (0.05 deg over the 10 mm thread moves its
// far side 4 um) the nut runs down as an aligned one does; at 3 deg (0.26 mm, a sixth of a
// pitch) its first turns meet the bolt's on the wrong flanks and the torque reaches the wrench's
// 40 N*m before the face.
TEST(Tightening, ACrossThreadedStartJamsBeforeTheFace) {
  const std::string crooked =
      test_support::ReadText(test_support::ShippedScenario("cross-thread.yaml"));
  const std::vector<Tick> jammed = Tighten(crooked, 1, 8.0);
  EXPECT_TRUE(jammed.back().screw.stopped);
  EXPECT_FALSE(jammed.back().screw.seated);
  EXPECT_GE(jammed.back().screw.torque, 40.0);
  const std::vector<Tick> clean =
      Tighten(Replaced(crooked, "tilt: 3 deg", "tilt: 0.05 deg"), 1, 8.0);
  EXPECT_TRUE(clean.back().screw.seated);
  double rundown = 0.0;
  for (const Tick& t : clean) {
    if (!t.screw.seated) rundown = std::max(rundown, t.screw.torque);
  }
  EXPECT_LT(rundown, 0.05);
}

// Fingers run the nut down to the face (the scripted hand, its wrist turning the nut through the
// grip's torsional spring): free running, seated, finger-tight, and passive.
TEST(Tightening, AHandRunsTheNutDownToTheFace) {
  const RunResult run = RunScene(LoadScene(test_support::ShippedScenario("nut-by-hand.yaml"),
                                           test_support::BuildTreePlugins()),
                                 RunOptions{});
  const nlohmann::json& thread = run.summary["thread"];
  EXPECT_EQ(thread["start"], "seated");
  EXPECT_LT(thread["rundown_torque_Nm"].get<double>(), 0.05);
  // Finger-tight: a few newton metres at most, a kilonewton or two of preload.
  EXPECT_LT(thread["torque_Nm"].get<double>(), 5.0);
  EXPECT_GT(thread["preload_N"].get<double>(), 0.0);
  EXPECT_EQ(run.summary["safety"]["energy_created_J"].get<double>(), 0.0);
}

}  // namespace
}  // namespace fitfeel::thread
