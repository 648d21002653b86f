#include "framework/plot/sms_chart.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plot/render.h"
#include "framework/plot/test/synthetic_sms.h"
#include "framework/plot/test/test_support.h"

namespace fitfeel::plot {
namespace {

using ::testing::HasSubstr;
using testing::kBushing;
using testing::kShaft;
using testing::ScratchDir;
using testing::SyntheticPart;
using testing::SyntheticSms;

TEST(Limits, HalfTheDiametralDeviations) {
  const RadialLimits v = VariationLimits(kShaft);
  EXPECT_DOUBLE_EQ(v.lower, -3.25e-6);
  EXPECT_DOUBLE_EQ(v.upper, 3.25e-6);
  const RadialLimits s = ToleranceSpaceLimits(kShaft, kBushing);
  EXPECT_DOUBLE_EQ(s.lower, -3.25e-6);  // (EI - es) / 2: a transition fit can interfere
  EXPECT_DOUBLE_EQ(s.upper, 13.75e-6);  // (ES - ei) / 2
}

TEST(MakeSkinProfileMap, UnwrapsRowsAndColumnsInMicrometresAndDegrees) {
  const SkinModelShape sms = SyntheticSms(kShaft, 40, 72, 60e-3, 0.0);
  const HeatMap map = MakeSkinProfileMap(kShaft, sms);
  ASSERT_EQ(map.values.rows(), 40);
  ASSERT_EQ(map.values.cols(), 72);
  EXPECT_NEAR(map.x(0), 0.75, 1e-12);   // mm
  EXPECT_NEAR(map.y(71), 357.5, 1e-9);  // degrees
  EXPECT_NEAR(map.values(3, 5), sms.variation(3 * 72 + 5) * 1e6, 1e-12);
  EXPECT_DOUBLE_EQ(*map.colour_min, -3.25);
  EXPECT_DOUBLE_EQ(*map.colour_max, 3.25);
  ASSERT_EQ(map.colour_marks.size(), 2u);
  EXPECT_THAT(map.colour_marks[1].label, HasSubstr("es/2 +3.25 µm"));
  EXPECT_THAT(map.title, HasSubstr("20 mm js6"));
  EXPECT_THAT(map.colour_label, HasSubstr("(µm)"));
}

TEST(MakeSkinProfileMap, NegativeZeroLimitPrintsAsPlusZero) {
  const PartSpec bore = SyntheticPart("bore", Role::kOuter, -0.0, 21e-6, "H7");
  const HeatMap map = MakeSkinProfileMap(bore, SyntheticSms(bore, 10, 12, 20e-3, 0.0));
  EXPECT_EQ(map.colour_marks[0].label, "EI/2 +0.00 µm");
}

TEST(MakeSkinProfileMap, RefusesAShapeThatDoesNotMatchItsGrid) {
  SkinModelShape sms = SyntheticSms(kShaft, 10, 12, 60e-3, 0.0);
  sms.variation.conservativeResize(50);
  EXPECT_THROW(MakeSkinProfileMap(kShaft, sms), UserError);
}

TEST(MakeToleranceSpaceMap, MarksClearanceInterferenceAndContact) {
  ToleranceSpaceGrid space;
  space.axial = Eigen::VectorXd::LinSpaced(10, 0.5e-3, 9.5e-3);
  space.angle = Eigen::VectorXd::LinSpaced(12, 0.1, 6.0);
  space.value = Eigen::MatrixXd::Constant(10, 12, 2e-6);
  const HeatMap map = MakeToleranceSpaceMap(kShaft, kBushing, space, "at full insertion");
  ASSERT_EQ(map.colour_marks.size(), 3u);
  EXPECT_THAT(map.colour_marks[0].label, HasSubstr("max interference -3.25 µm"));
  EXPECT_THAT(map.colour_marks[1].label, HasSubstr("max clearance +13.75 µm"));
  EXPECT_EQ(map.colour_marks[2].value, 0.0);
  EXPECT_DOUBLE_EQ(map.values(0, 0), 2.0);
  space.value.resize(3, 3);
  EXPECT_THROW(MakeToleranceSpaceMap(kShaft, kBushing, space, "x"), UserError);
}

TEST(MakeSmsChart, RendersBothPartsAndTheToleranceSpace) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  const SkinModelShape shaft = SyntheticSms(kShaft, 60, 72, 60e-3, 0.0);
  const SkinModelShape bushing = SyntheticSms(kBushing, 20, 72, 20e-3, 1.0);
  ToleranceSpaceGrid space{bushing.grid.row_position, bushing.grid.column_angle,
                           Eigen::MatrixXd(20, 72)};
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 72; ++j) {
      space.value(i, j) = bushing.variation(i * 72 + j) - shaft.variation((i + 40) * 72 + j);
    }
  }
  const HeatMapChart chart =
      MakeSmsChart("paper-case1-h7js6",
                   {MakeSkinProfileMap(kShaft, shaft), MakeSkinProfileMap(kBushing, bushing),
                    MakeToleranceSpaceMap(kShaft, kBushing, space, "at full insertion")});
  Render(chart, ResolveOutputs(dir.path() / "sms"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "sms.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "sms.svg"));
}

}  // namespace
}  // namespace fitfeel::plot

namespace fitfeel::plot {
namespace {

// A shaft of 60 rows x 1 mm whose V encodes its row (0.1 um per row) and column (0.001 um per
// column), in a bushing of 20 rows x 1 mm with V = 10 um everywhere.
struct Pair {
  SkinModelShape shaft = testing::SyntheticSms(kShaft, 60, 72, 60e-3, 0.0);
  SkinModelShape bushing = testing::SyntheticSms(kBushing, 20, 72, 20e-3, 0.0);
  Pair() {
    for (int i = 0; i < 60; ++i) {
      for (int j = 0; j < 72; ++j) shaft.variation(shaft.grid.index(i, j)) = 1e-7 * i + 1e-9 * j;
    }
    bushing.variation.setConstant(10e-6);
  }
};

TEST(ToleranceSpaceAtDepth, FullInsertionFacesTheShaftsLeadingRows) {
  const Pair p;
  EXPECT_NEAR(MatingLength(p.shaft.grid), 60e-3, 1e-15);
  const double depth = FullInsertionDepth(p.shaft, p.bushing);
  EXPECT_NEAR(depth, 20e-3, 1e-15);
  const ToleranceSpaceGrid space = ToleranceSpaceAtDepth(p.shaft, p.bushing, depth, 4);
  ASSERT_EQ(space.axial.size(), 80);
  EXPECT_NEAR(space.axial(0), 0.125e-3, 1e-15);  // from the bushing's entrance
  // Next to the entrance sits the shaft's row 40 (20 mm behind its leading end), at the far end
  // its leading row 59.
  EXPECT_NEAR(space.value(0, 0), 10e-6 - 40e-7, 1e-15);
  EXPECT_NEAR(space.value(79, 5), 10e-6 - 59e-7 - 5e-9, 1e-15);
  EXPECT_NEAR(space.value(41, 0), 10e-6 - 50e-7, 1e-15);  // 10.375 mm in: row 50
}

TEST(ToleranceSpaceAtDepth, PartialDepthOverlapsOnlyTheEntrance) {
  const Pair p;
  const ToleranceSpaceGrid space = ToleranceSpaceAtDepth(p.shaft, p.bushing, 5e-3, 4);
  EXPECT_NEAR(space.axial(space.axial.size() - 1), 5e-3 - 0.125e-3, 1e-12);
  EXPECT_NEAR(space.value(0, 0), 10e-6 - 55e-7, 1e-15);
  // Past the bushing (depth > its length), the shaft's trailing part leaves through its far end.
  const ToleranceSpaceGrid late = ToleranceSpaceAtDepth(p.shaft, p.bushing, 70e-3, 4);
  EXPECT_NEAR(late.axial(0), 10e-3 + 0.125e-3, 1e-12);
  EXPECT_NEAR(late.value(0, 0), 10e-6, 1e-15);  // shaft row 0 faces 10 mm past the entrance
}

TEST(ToleranceSpaceAtDepth, NoOverlapIsRefused) {
  const Pair p;
  EXPECT_THROW(ToleranceSpaceAtDepth(p.shaft, p.bushing, 0.0), UserError);
  EXPECT_THROW(ToleranceSpaceAtDepth(p.shaft, p.bushing, 80e-3), UserError);
  EXPECT_THROW(ToleranceSpaceAtDepth(p.shaft, p.bushing, -1e-3), UserError);
}

TEST(ToleranceSpaceAtDepth, ColumnsFaceTheNearestAngle) {
  Pair p;
  p.bushing = testing::SyntheticSms(kBushing, 20, 36, 20e-3, 0.0);
  for (int i = 0; i < 20; ++i) {
    for (int k = 0; k < 36; ++k) p.bushing.variation(p.bushing.grid.index(i, k)) = 1e-6 * k;
  }
  const ToleranceSpaceGrid space = ToleranceSpaceAtDepth(p.shaft, p.bushing, 20e-3, 1);
  // Shaft column j at (j + 0.5) * 5 deg; bushing column k at (k + 0.5) * 10 deg: j = 10 (52.5 deg)
  // is nearest to k = 5 (55 deg), j = 71 (357.5 deg) to k = 35 (355 deg).
  EXPECT_NEAR(space.value(0, 10), 5e-6 - 40e-7 - 10e-9, 1e-15);
  EXPECT_NEAR(space.value(0, 71), 35e-6 - 40e-7 - 71e-9, 1e-15);
}

}  // namespace
}  // namespace fitfeel::plot
