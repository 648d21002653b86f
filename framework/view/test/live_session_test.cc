#include "framework/view/live_session.h"

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/testing/build_tree_plugins.h"

namespace fitfeel::view {
namespace {

// Passes in virtual time: each a whole run of the scene's 4 s stroke, at once.
LiveSessionOptions VirtualPasses() {
  LiveSessionOptions options;
  options.clock = ClockMode::kVirtual;
  options.server.log = [](const std::string&) {};
  return options;
}

std::string Edit(const std::string& path, const std::string& value, const std::string& apply) {
  return nlohmann::json{{"type", "edit"}, {"edits", {{path, value}}}, {"apply", apply}}.dump();
}

TEST(LiveSession, AnEditedClassIsPreparedOffTheTickAndRendersFromTheNextPass) {
  LiveSession session("scenarios/fits-20mm-h7js6.yaml", std::nullopt,
                      test_support::BuildTreePlugins(), VirtualPasses());
  EXPECT_EQ(session.panel()["mode"], "edit");
  session.Run(1);
  // js6 with this seed clears: the shaft's weight, 2 N at friction 0.15.
  const double js6 = session.last_pass_peak();
  EXPECT_GT(js6, 0.29);
  EXPECT_LT(js6, 0.31);

  session.Submit(Edit("parts.shaft.size", "20 mm k6", "check"));
  session.Drain();
  EXPECT_EQ(session.panel()["edit"]["state"], "valid");
  EXPECT_FALSE(session.panel()["pending"].get<bool>());  // checked, not applied

  session.Submit(Edit("parts.shaft.size", "20 mm k6", "free"));
  session.Drain();
  const nlohmann::json waiting = session.panel();
  EXPECT_EQ(waiting["edit"]["state"], "waiting for the part to be out of contact");
  EXPECT_TRUE(waiting["pending"].get<bool>());
  EXPECT_GT(waiting["edit"]["prepare_ms"].get<double>(), 0.0);
  // The newest scene's fields are the edited one's: the page edits on from there.
  bool k6 = false;
  for (const nlohmann::json& f : waiting["fields"]) k6 = k6 || f["value"] == "20 mm k6";
  EXPECT_TRUE(k6);
  EXPECT_EQ(session.panel()["fit"], "H7/k6");

  session.Run(2);
  EXPECT_EQ(session.swaps(), 1u);
  // k6 presses: DIN 7190's order of a kilonewton over this 20 mm joint (the seven fits' table).
  EXPECT_GT(session.last_pass_peak(), 200.0);
  EXPECT_FALSE(session.panel()["pending"].get<bool>());
  EXPECT_EQ(session.panel()["edit"]["state"], "applied");
}

TEST(LiveSession, ARefusedEditIsShownWithItsLocatedMessageAndTheRunGoesOnUntouched) {
  LiveSession session("scenarios/paper-case1-h7js6.yaml", std::nullopt,
                      test_support::BuildTreePlugins(), VirtualPasses());
  session.Run(1);
  const double before = session.last_pass_peak();
  session.Submit(Edit("model.friction", "sticky", "now"));
  session.Submit("not json");
  session.Submit(Edit("device.speed", "1 m/s", "now"));
  session.Drain();
  const nlohmann::json panel = session.panel();
  EXPECT_EQ(panel["edit"]["state"], "refused");
  EXPECT_EQ(panel["edit"]["key_path"], "device.speed");
  EXPECT_FALSE(panel["pending"].get<bool>());

  session.Submit(R"({"type":"edit","edits":{"model.friction":0.2},"apply":7})");
  session.Submit(R"({"type":"select","scene":1,"now":"yes"})");
  session.Submit(R"({"type":"edit","edits":[1,2]})");
  session.Drain();
  EXPECT_EQ(session.panel()["edit"]["state"], "refused");
  session.Submit(Edit("model.friction", "sticky", "now"));
  session.Drain();
  const std::string message = session.panel()["edit"]["message"];
  EXPECT_EQ(session.panel()["edit"]["key_path"], "model.friction");
  EXPECT_NE(message.find("paper-case1-h7js6.yaml:"), std::string::npos) << message;
  EXPECT_NE(message.find("sticky"), std::string::npos) << message;

  session.Run(2);
  EXPECT_EQ(session.swaps(), 0u);
  // The same scene, the same pass: bit for bit.
  EXPECT_EQ(session.last_pass_peak(), before);
}

TEST(LiveSession, AComparisonRendersTheSelectedSceneAndSwitchesBack) {
  LiveSession session("scenarios/paper-case1-h7g6.yaml",
                      std::filesystem::path("scenarios/paper-case1-h7js6.yaml"),
                      test_support::BuildTreePlugins(), VirtualPasses());
  const nlohmann::json panel = session.panel();
  EXPECT_EQ(panel["mode"], "compare");
  EXPECT_EQ(panel["compare"]["scenes"][0]["fit"], "H7/g6");
  EXPECT_EQ(panel["compare"]["rendering"], 0);
  session.Run(1);
  const double g6 = session.last_pass_peak();
  EXPECT_LT(g6, 1.0);  // clearance: the weight's friction

  session.Submit(R"({"type":"select","scene":1,"now":true})");
  session.Drain();
  EXPECT_EQ(session.rendering(), "paper-case1-h7js6");
  session.Run(2);
  EXPECT_EQ(session.panel()["compare"]["rendering"], 1);
  // The paper's js6 pair: its form deviations press near the end of the stroke, 10.3 N.
  EXPECT_GT(session.last_pass_peak(), 10.0);
  EXPECT_LT(session.last_pass_peak(), 11.0);

  session.Submit(R"({"type":"select","scene":0,"now":"yes"})");  // refused, said in the page
  session.Drain();
  EXPECT_EQ(session.panel()["edit"]["state"], "refused");
  session.Submit(R"({"type":"select","scene":0})");
  session.Drain();
  session.Run(3);
  EXPECT_EQ(session.swaps(), 2u);
  EXPECT_EQ(session.last_pass_peak(), g6);  // A again, bit for bit
  // Edits belong to an edit session, not a comparison.
  session.Submit(R"({"type":"edit","edits":{"model.friction":"0.2"},"apply":"now"})");
  session.Drain();
  EXPECT_FALSE(session.panel()["pending"].get<bool>());
}

TEST(LiveSession, RefusesASequence) {
  EXPECT_THROW(LiveSession("scenarios/key-then-hub.yaml", std::nullopt,
                           test_support::BuildTreePlugins(), VirtualPasses()),
               UserError);
}

}  // namespace
}  // namespace fitfeel::view
