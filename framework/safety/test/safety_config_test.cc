#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"
#include "framework/safety/safety_chain.h"

namespace fitfeel {
namespace {

ConfigNode SafetyNode(const std::string& text) {
  return ConfigNode::Parse(text, "scene.yaml", "safety");
}

TEST(SafetyConfig, ParsesEveryKey) {
  const SafetySettings s = ParseSafetySettings(
      SafetyNode("{force_scale: 0.01, continuous_window: 5 s, coupling: direct,"
                 " coupling_stiffness: 500 N/m, coupling_damping: 1 N*s/m, proxy_mass: 10 g,"
                 " credit_device_damping: false, passivity_controller: true,"
                 " passivity_max_damping: 2 N*s/m}"));
  EXPECT_DOUBLE_EQ(s.force_scale, 0.01);
  EXPECT_DOUBLE_EQ(s.continuous_window, 5.0);
  EXPECT_EQ(s.coupling, CouplingMode::kDirect);
  EXPECT_DOUBLE_EQ(*s.coupling_stiffness, 500.0);
  EXPECT_DOUBLE_EQ(*s.coupling_damping, 1.0);
  EXPECT_DOUBLE_EQ(s.proxy_mass, 0.01);
  EXPECT_FALSE(s.credit_device_damping);
  EXPECT_TRUE(s.passivity_controller);
  EXPECT_DOUBLE_EQ(*s.passivity_max_damping, 2.0);
}

TEST(SafetyConfig, EmptySectionGivesDefaults) {
  const SafetySettings s = ParseSafetySettings(SafetyNode("{}"));
  EXPECT_DOUBLE_EQ(s.force_scale, 1.0);
  EXPECT_EQ(s.coupling, CouplingMode::kSpringDamper);
  SafetyChain chain;
  chain.Configure(SafetySettings{}, LookupDeviceSpec("Touch"), 1e-3);
  EXPECT_DOUBLE_EQ(chain.report().coupling_gains.stiffness, 320.0);
}

TEST(SafetyConfig, RefusesBadInput) {
  EXPECT_THROW(ParseSafetySettings(SafetyNode("{force_scale: 0.01, physical_full_scale: 300 N}")),
               ScenarioError);
  EXPECT_THROW(ParseSafetySettings(SafetyNode("{force_scale: -1}")), ScenarioError);
  EXPECT_THROW(ParseSafetySettings(SafetyNode("{coupling: magic}")), ScenarioError);
  EXPECT_THROW(ParseSafetySettings(SafetyNode("{scale: 1}")), ScenarioError);
  EXPECT_THROW(ParseSafetySettings(SafetyNode("{physical_full_scale: 300 mm}")), ScenarioError);
}

}  // namespace
}  // namespace fitfeel
