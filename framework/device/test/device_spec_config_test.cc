#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"

namespace fitfeel {
namespace {

ConfigNode SpecNode(const std::string& text) {
  return ConfigNode::Parse(text, "scene.yaml", "device.spec");
}

TEST(DeviceSpecConfig, OverridesAnyField) {
  const DeviceSpec spec = ParseDeviceSpec(
      SpecNode(
          "{model: touch, max_force: 2.5 N, max_continuous_force: 0.5 N, max_stiffness: 0.3 N/mm,"
          " damping: 3 N*s/m, workspace: [100 mm, 80 mm, 60 mm], native_rate: 2 kHz}"),
      LookupDeviceSpec("PHANTOM Desktop"));
  EXPECT_EQ(spec.model, "Touch");
  EXPECT_DOUBLE_EQ(spec.max_force, 2.5);
  EXPECT_DOUBLE_EQ(spec.max_continuous_force, 0.5);
  EXPECT_DOUBLE_EQ(spec.max_stiffness, 300.0);
  EXPECT_DOUBLE_EQ(spec.damping, 3.0);
  EXPECT_NEAR(spec.workspace.z(), 0.06, 1e-15);
  EXPECT_DOUBLE_EQ(spec.native_rate, 2000.0);
}

TEST(DeviceSpecConfig, SelectsTheForceMapping) {
  const DeviceSpec base = LookupDeviceSpec("Touch");
  EXPECT_EQ(ParseDeviceSpec(SpecNode("{force_mapping: perceptual}"), base).force_mapping,
            ForceMappingKind::kPerceptual);
  EXPECT_EQ(
      ParseDeviceSpec(SpecNode("{model: premium-3.0, force_mapping: linear}"), base).force_mapping,
      ForceMappingKind::kLinear);
  try {
    ParseDeviceSpec(SpecNode("{force_mapping: cubic}"), base);
    FAIL() << "no throw";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("device.spec.force_mapping"), std::string::npos)
        << e.what();
  }
}

TEST(DeviceSpecConfig, KeepsTheBaseForFieldsNotGiven) {
  const DeviceSpec spec =
      ParseDeviceSpec(SpecNode("{max_force: 5 N}"), LookupDeviceSpec("Desktop"));
  EXPECT_DOUBLE_EQ(spec.max_force, 5.0);
  EXPECT_DOUBLE_EQ(spec.max_stiffness, 1000.0);
}

TEST(DeviceSpecConfig, RefusesBadValuesWithTheKey) {
  const DeviceSpec base = LookupDeviceSpec("Desktop");
  EXPECT_THROW(ParseDeviceSpec(SpecNode("{max_force: 5 mm}"), base), ScenarioError);
  EXPECT_THROW(ParseDeviceSpec(SpecNode("{max_force: -1 N}"), base), ScenarioError);
  EXPECT_THROW(ParseDeviceSpec(SpecNode("{colour: red}"), base), ScenarioError);
  EXPECT_THROW(ParseDeviceSpec(SpecNode("{model: falcon}"), base), ScenarioError);
  EXPECT_THROW(ParseDeviceSpec(SpecNode("{workspace: [1 mm, 2 mm]}"), base), ScenarioError);
  EXPECT_THROW(ParseDeviceSpec(SpecNode("{max_continuous_force: 9 N}"), base), ScenarioError);
}

}  // namespace
}  // namespace fitfeel
