#include "surfaces/cylindrical/sms_conformance.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace fitfeel::cylindrical {
namespace {

// A hand-made skin model shape: ovality 2a (roundness 2a, two-point sizes +-2a about 2 v0).
TEST(SmsConformance, ReportsEachCharacteristicAgainstItsLimit) {
  SkinModelShape sms;
  SurfaceGrid& g = sms.grid;
  g.rows = 4;
  g.columns = 16;
  g.row_position = Eigen::VectorXd::LinSpaced(4, 0.0, 0.015);
  g.column_angle.resize(16);
  for (int j = 0; j < 16; ++j) g.column_angle(j) = 2.0 * std::numbers::pi * j / 16;
  sms.variation.resize(64);
  const double a = 2e-6, v0 = 1e-6;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 16; ++j)
      sms.variation(g.index(i, j)) = v0 + a * std::cos(2 * g.column_angle(j));
  sms.surface_part = Eigen::VectorXd::Zero(64);
  PartSpec part;
  part.size.nominal = 0.02;
  part.size.lower_deviation = -4e-6;
  part.size.upper_deviation = 6e-6;
  part.form.tolerance[FormCharacteristic::kRoundness] = 4e-6;
  part.form.tolerance[FormCharacteristic::kAxisStraightness] = 1e-6;
  ConformanceReport report = EvaluateCylindricalSms(part, sms);
  const auto* size = report.Find("size");
  ASSERT_NE(size, nullptr);
  EXPECT_NEAR(size->value_low, 2 * v0 - 2 * a, 1e-18);
  EXPECT_NEAR(size->value, 2 * v0 + 2 * a, 1e-18);
  EXPECT_TRUE(size->pass);
  EXPECT_NEAR(report.Find("roundness")->value, 2 * a, 1e-12);
  EXPECT_TRUE(report.Find("roundness")->pass);
  EXPECT_FALSE(report.Find("cylindricity")->specified);
  EXPECT_TRUE(report.AllPass());
  // Tighter roundness and size limits fail.
  part.form.tolerance[FormCharacteristic::kRoundness] = 3.9e-6;
  part.size.upper_deviation = 5.9e-6;
  report = EvaluateCylindricalSms(part, sms);
  EXPECT_FALSE(report.Find("roundness")->pass);
  EXPECT_FALSE(report.Find("size")->pass);
  EXPECT_FALSE(report.AllPass());
}

}  // namespace
}  // namespace fitfeel::cylindrical
