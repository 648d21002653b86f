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

// SensAble's PHANTOM Premium data sheets; the damping is the passivity bound's K T / 2 at 1 kHz,
// which the observer may not credit.
TEST(DeviceSpecs, PremiumModels) {
  struct Expected {
    const char* alias;
    const char* model;
    double peak, continuous, stiffness;
    Eigen::Vector3d workspace;
  };
  const Expected expected[] = {
      {"premium-1.0", "PHANTOM Premium 1.0", 8.5, 1.4, 3500.0, {0.254, 0.178, 0.127}},
      {"premium-1.5", "PHANTOM Premium 1.5", 8.5, 1.4, 3500.0, {0.381, 0.267, 0.191}},
      {"premium-1.5-hf",
       "PHANTOM Premium 1.5 High Force",
       37.5,
       6.2,
       3500.0,
       {0.381, 0.267, 0.191}},
      {"premium-3.0", "PHANTOM Premium 3.0", 22.0, 3.0, 1000.0, {0.838, 0.584, 0.406}},
  };
  for (const Expected& e : expected) {
    const DeviceSpec spec = LookupDeviceSpec(e.alias);
    EXPECT_EQ(spec.model, e.model);
    EXPECT_EQ(LookupDeviceSpec(e.model).model, e.model);
    EXPECT_DOUBLE_EQ(spec.max_force, e.peak) << e.model;
    EXPECT_DOUBLE_EQ(spec.max_continuous_force, e.continuous) << e.model;
    EXPECT_DOUBLE_EQ(spec.max_stiffness, e.stiffness) << e.model;
    EXPECT_DOUBLE_EQ(spec.damping, e.stiffness * 1e-3 / 2.0) << e.model;
    EXPECT_FALSE(spec.credit_damping) << e.model;
    EXPECT_TRUE(spec.workspace.isApprox(e.workspace)) << e.model;
    EXPECT_EQ(spec.force_mapping, ForceMappingKind::kLinear) << e.model;
  }
  EXPECT_EQ(LookupDeviceSpec("premium1.5highforce").model, "PHANTOM Premium 1.5 High Force");
  EXPECT_EQ(LookupDeviceSpec("Premium 1.5 High Force").model, "PHANTOM Premium 1.5 High Force");
  EXPECT_EQ(LookupDeviceSpec("phantom_premium_1.5_hf").model, "PHANTOM Premium 1.5 High Force");
  EXPECT_EQ(LookupDeviceSpec("Premium 3.0").model, "PHANTOM Premium 3.0");
  EXPECT_FALSE(FindDeviceSpec("premium").has_value());
  EXPECT_FALSE(FindDeviceSpec("premium-2.0").has_value());
  // The older models keep crediting their measured damping.
  EXPECT_TRUE(LookupDeviceSpec("Touch").credit_damping);
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
    EXPECT_NE(what.find("PHANTOM Premium 1.5 High Force"), std::string::npos) << what;
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
