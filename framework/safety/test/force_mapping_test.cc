#include "framework/safety/force_mapping.h"

#include <cmath>
#include <limits>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/device/device_specs.h"
#include "framework/safety/safety_chain.h"

namespace fitfeel {
namespace {

using ::testing::HasSubstr;

// The Touch's top: its continuous rating held for one thermal time constant.
const double kTouchTop = 0.88 / std::sqrt(1.0 - std::exp(-1.0));

ForceMapping TouchMap() { return ForceMapping::Perceptual(0.1, 20e3, kTouchTop); }

TEST(ForceMapping, DeviceTopOfATouchIsItsContinuousRatingOverOneWindow) {
  EXPECT_DOUBLE_EQ(PerceptualDeviceTop(LookupDeviceSpec("touch")), kTouchTop);
  EXPECT_NEAR(kTouchTop, 1.107, 1e-3);
  // A device without a motor: only perception bounds the top.
  DeviceSpec robot;
  robot.max_force = robot.max_continuous_force = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(PerceptualDeviceTop(robot), kPerceptionSaturationForce);
  // A strong device: perception again (its thermal top 6.2 / 0.795 = 7.8 N is above it).
  EXPECT_DOUBLE_EQ(PerceptualDeviceTop(LookupDeviceSpec("premium-1.5-hf")),
                   kPerceptionSaturationForce);
}

TEST(ForceMapping, IdentityBelowTheKneeAndTopOnTop) {
  const ForceMapping m = TouchMap();
  EXPECT_EQ(m.kind(), ForceMappingKind::kPerceptual);
  for (double f : {1e-6, 1e-3, 0.05, 0.0999, 0.1}) EXPECT_DOUBLE_EQ(m.Map(f), f) << f;
  EXPECT_DOUBLE_EQ(m.Map(20e3), kTouchTop);
  EXPECT_DOUBLE_EQ(m.exponent(), std::log(kTouchTop / 0.1) / std::log(20e3 / 0.1));
  EXPECT_DOUBLE_EQ(m.Map(0.0), 0.0);
  EXPECT_DOUBLE_EQ(m.Map(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(m.Map(std::numeric_limits<double>::quiet_NaN()), 0.0);
  EXPECT_DOUBLE_EQ(m.Ratio(0.0), 1.0);
  EXPECT_DOUBLE_EQ(m.Slope(0.0), 1.0);
}

TEST(ForceMapping, ContinuousAtTheKnee) {
  const ForceMapping m = TouchMap();
  const double eps = 1e-9;
  EXPECT_NEAR(m.Map(0.1 - eps), 0.1, 2 * eps);
  EXPECT_NEAR(m.Map(0.1 + eps), 0.1, 2 * eps);
}

// Monotone, slope at most 1 and never increasing (concave) over twelve decades, checked by
// differences on a dense logarithmic grid.
TEST(ForceMapping, MonotoneConcaveAndNeverSteeperThanOne) {
  const ForceMapping m = TouchMap();
  const int n = 20000;
  double previous_f = 1e-6, previous_map = m.Map(previous_f), previous_slope = 1.0;
  for (int k = 1; k <= n; ++k) {
    const double f = 1e-6 * std::pow(10.0, 12.0 * k / n);
    const double mapped = m.Map(f);
    ASSERT_GT(mapped, previous_map) << f;
    const double slope = (mapped - previous_map) / (f - previous_f);
    ASSERT_LE(slope, 1.0 + 1e-9) << f;
    ASSERT_LE(slope, previous_slope * (1.0 + 1e-6)) << f;
    ASSERT_LE(m.Slope(f), 1.0) << f;
    ASSERT_LE(m.Ratio(f), 1.0) << f;
    previous_f = f;
    previous_map = mapped;
    previous_slope = slope;
  }
}

TEST(ForceMapping, LinearIsTheScale) {
  const ForceMapping m = ForceMapping::Linear(0.01);
  EXPECT_EQ(m.kind(), ForceMappingKind::kLinear);
  for (double f : {1e-3, 0.3, 10.0, 18e3}) EXPECT_DOUBLE_EQ(m.Map(f), 0.01 * f) << f;
  EXPECT_DOUBLE_EQ(m.Slope(5.0), 0.01);
  EXPECT_DOUBLE_EQ(m.Ratio(0.0), 0.01);
  EXPECT_THROW(ForceMapping::Linear(0.0), UserError);
}

TEST(ForceMapping, RefusesAKneeOrTopOutOfOrder) {
  EXPECT_THROW(ForceMapping::Perceptual(0.0, 20e3, 1.0), UserError);
  EXPECT_THROW(ForceMapping::Perceptual(2.0, 20e3, 1.0), UserError);  // knee above device top
  EXPECT_THROW(ForceMapping::Perceptual(0.1, 1.0, 2.0), UserError);   // slope above 1
}

TEST(ForceMapping, ChainKeepsTheDirectionAndScalesTheTorqueAlike) {
  SafetySettings s;
  s.coupling = CouplingMode::kDirect;
  s.force_mapping = ForceMappingKind::kPerceptual;
  SafetyChain chain;
  chain.Configure(s, LookupDeviceSpec("Touch"), 1e-3);
  Wrench w;
  w.force = Eigen::Vector3d(0.0, -3000.0, 4000.0);  // 5 kN
  w.torque = Eigen::Vector3d(0.0, 10.0, 0.0);
  const Wrench out = chain.Apply(w, PartState{}, 1e-3);
  const double f = chain.mapping().Map(5000.0);
  EXPECT_NEAR(out.force.norm(), f, 1e-12);
  EXPECT_NEAR(out.force.y() / out.force.z(), -0.75, 1e-12);
  EXPECT_NEAR(out.torque.y(), 10.0 * f / 5000.0, 1e-15);
  EXPECT_DOUBLE_EQ(chain.stiffness_scale(), chain.mapping().Slope(5000.0));
  EXPECT_THAT(FormatSafetyReport(chain.report()),
              HasSubstr("force mapping: perceptual, knee 0.1 N"));
}

TEST(ForceMapping, SettingsChooseOverTheSpec) {
  DeviceSpec touch = LookupDeviceSpec("Touch");
  touch.force_mapping = ForceMappingKind::kPerceptual;
  SafetySettings s;
  s.coupling = CouplingMode::kDirect;
  SafetyChain chain;
  chain.Configure(s, touch, 1e-3);
  EXPECT_EQ(chain.mapping().kind(), ForceMappingKind::kPerceptual);
  s.force_mapping = ForceMappingKind::kLinear;
  s.force_scale = 0.01;
  chain.Configure(s, touch, 1e-3);
  EXPECT_EQ(chain.mapping().kind(), ForceMappingKind::kLinear);
  EXPECT_DOUBLE_EQ(chain.mapping().scale(), 0.01);
}

ConfigNode MappingSafetyNode(const std::string& text) {
  return ConfigNode::Parse(text, "scene.yaml", "safety");
}

std::string MappingParseError(const std::string& text) {
  try {
    ParseSafetySettings(MappingSafetyNode(text));
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ForceMappingConfig, ParsesTheKeys) {
  const SafetySettings s = ParseSafetySettings(
      MappingSafetyNode("{force_mapping: perceptual, mapping_knee: 50 mN, mapping_top: 5 kN}"));
  EXPECT_EQ(s.force_mapping, ForceMappingKind::kPerceptual);
  EXPECT_DOUBLE_EQ(s.mapping_knee, 0.05);
  EXPECT_DOUBLE_EQ(s.mapping_top, 5e3);
  EXPECT_FALSE(ParseSafetySettings(MappingSafetyNode("{}")).force_mapping.has_value());
  // A scale is a linear mapping, whatever the device's spec prefers.
  EXPECT_EQ(ParseSafetySettings(MappingSafetyNode("{force_scale: 0.01}")).force_mapping,
            ForceMappingKind::kLinear);
}

TEST(ForceMappingConfig, ErrorsAreLocatedAtTheirKeys) {
  EXPECT_THAT(MappingParseError("{force_mapping: logarithmic}"), HasSubstr("safety.force_mapping"));
  EXPECT_THAT(MappingParseError("{mapping_knee: 0.1 m}"), HasSubstr("safety.mapping_knee"));
  EXPECT_THAT(MappingParseError("{mapping_knee: -1 N}"), HasSubstr("safety.mapping_knee"));
  EXPECT_THAT(MappingParseError("{mapping_top: 0 N}"), HasSubstr("safety.mapping_top"));
  EXPECT_THAT(MappingParseError("{mapping_knee: 2 N, mapping_top: 1 N}"),
              HasSubstr("safety.mapping_knee"));
  EXPECT_THAT(MappingParseError("{mapping_top: 0.05 N}"), HasSubstr("safety.mapping_top"));
  const std::string both = MappingParseError("{force_mapping: perceptual, force_scale: 0.01}");
  EXPECT_THAT(both, HasSubstr("safety.force_scale"));
  EXPECT_THAT(both, HasSubstr("force_mapping: perceptual"));
  EXPECT_THAT(MappingParseError("{force_mapping: perceptual, physical_full_scale: 300 N}"),
              HasSubstr("safety.physical_full_scale"));
  EXPECT_EQ(MappingParseError("{force_mapping: linear, force_scale: 0.01}"), "no error");
}

}  // namespace
}  // namespace fitfeel
