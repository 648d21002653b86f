#include "framework/device/device_specs.h"

#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

// Oracle: docs/oracles.md, "Haptic stability and devices".
TEST(DeviceSpecs, OracleValues) {
  const DeviceSpec desktop = LookupDeviceSpec("PHANTOM Desktop");
  EXPECT_DOUBLE_EQ(desktop.max_force, 7.9);
  EXPECT_DOUBLE_EQ(desktop.max_stiffness, 1000.0);
  EXPECT_DOUBLE_EQ(desktop.damping, 5.0);
  const DeviceSpec omni = LookupDeviceSpec("PHANTOM Omni");
  EXPECT_DOUBLE_EQ(omni.max_force, 3.3);
  EXPECT_DOUBLE_EQ(omni.max_stiffness, 700.0);
  EXPECT_DOUBLE_EQ(omni.damping, 5.0);
  const DeviceSpec touch = LookupDeviceSpec("Touch");
  EXPECT_DOUBLE_EQ(touch.max_force, 3.3);
  EXPECT_DOUBLE_EQ(touch.max_stiffness, 400.0);
  EXPECT_DOUBLE_EQ(touch.damping, 4.0);
  for (const DeviceSpec& spec : KnownDeviceSpecs()) {
    EXPECT_DOUBLE_EQ(spec.native_rate, 1000.0);
    EXPECT_NO_THROW(ValidateDeviceSpec(spec)) << spec.model;
    EXPECT_LT(spec.max_continuous_force, spec.max_force);
  }
}

TEST(DeviceSpecs, LookupIgnoresCaseSpacesAndKnowsAliases) {
  EXPECT_EQ(LookupDeviceSpec("phantom-desktop").model, "PHANTOM Desktop");
  EXPECT_EQ(LookupDeviceSpec("  Omni ").model, "PHANTOM Omni");
  EXPECT_EQ(LookupDeviceSpec("Geomagic Touch").model, "Touch");
  EXPECT_EQ(LookupDeviceSpec("TOUCH").model, "Touch");
  EXPECT_FALSE(FindDeviceSpec("").has_value());
}

TEST(DeviceSpecs, UnknownModelNamesTheKnownOnes) {
  try {
    LookupDeviceSpec("Falcon");
    FAIL() << "no throw";
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'Falcon'"), std::string::npos) << what;
    EXPECT_NE(what.find("PHANTOM Desktop"), std::string::npos) << what;
    EXPECT_NE(what.find("Touch"), std::string::npos) << what;
  }
}

TEST(DeviceSpecs, ValidationRefusesBadLimits) {
  DeviceSpec spec = LookupDeviceSpec("Touch");
  spec.max_continuous_force = 4.0;  // above the 3.3 N peak
  EXPECT_THROW(ValidateDeviceSpec(spec), UserError);
  spec = LookupDeviceSpec("Touch");
  spec.damping = 0.0;
  EXPECT_THROW(ValidateDeviceSpec(spec), UserError);
  spec = LookupDeviceSpec("Touch");
  spec.workspace.y() = -0.1;
  EXPECT_THROW(ValidateDeviceSpec(spec), UserError);
  EXPECT_THROW(ValidateDeviceSpec(DeviceSpec{}), UserError);
}

}  // namespace
}  // namespace fitfeel
