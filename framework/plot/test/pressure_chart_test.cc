#include "framework/plot/pressure_chart.h"

#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plot/render.h"
#include "framework/plot/test/synthetic_sms.h"
#include "framework/plot/test/test_support.h"

namespace fitfeel::plot {
namespace {

using ::testing::HasSubstr;
using testing::ScratchDir;

ConstrainedTrace Trace() {
  ConstrainedTrace trace;
  for (int k = 0; k <= 100; ++k) {
    trace.t_s.push_back(0.001 * k);
    trace.depth_mm.push_back(0.2 * k);
    trace.fx_N.push_back(0.0);
    trace.fy_N.push_back(-k);
    trace.fz_N.push_back(2.0);
  }
  return trace;
}

TEST(RowAtDepth, FindsTheNearestRow) {
  const ConstrainedTrace trace = Trace();
  EXPECT_EQ(RowAtDepth(trace, 10.09), 50u);
  EXPECT_EQ(RowAtDepth(trace, 0.0), 0u);
  EXPECT_EQ(RowAtDepth(trace, 20.0), 100u);
}

TEST(RowAtDepth, RefusesADepthOutsideTheRun) {
  const ConstrainedTrace trace = Trace();
  for (double depth : {-0.1, 20.01, 100.0}) {
    try {
      RowAtDepth(trace, depth);
      FAIL() << "depth " << depth << " accepted";
    } catch (const UserError& e) {
      EXPECT_THAT(e.what(), HasSubstr("outside the run's constrained depth range 0.000 mm to "
                                      "20.000 mm"));
    }
  }
  EXPECT_THROW(RowAtDepth(trace, std::nan("")), UserError);
}

PressureMapData Data() {
  const PartSpec shaft = testing::SyntheticPart("shaft", Role::kInner, -6.5e-6, 6.5e-6, "js6");
  PressureMapData data;
  data.scenario = "paper-case1-h7js6";
  data.law = "gps";
  data.depth_mm = 12.0;
  data.grid = testing::SyntheticSms(shaft, 30, 72, 60e-3, 0.0).grid;
  data.interference = Eigen::VectorXd::Zero(data.grid.size());
  for (int i = 10; i < 20; ++i) {
    for (int j = 30; j < 50; ++j) data.interference(data.grid.index(i, j)) = 1e-6;
  }
  // Lamé pressure per unit radial interference of the oracle's steel example: 5.8333 MPa per um.
  data.pressure_per_interference = 5.8333e12;
  data.fx_N = 0.0;
  data.fy_N = -350.0;
  data.fz_N = -2.0;
  data.force_depth_mm = 12.0;
  return data;
}

TEST(MakePressureChart, PressureIsCoefficientTimesInterferenceInMegapascal) {
  const HeatMapChart chart = MakePressureChart(Data());
  ASSERT_EQ(chart.panels.size(), 1u);
  const HeatMap& map = chart.panels[0];
  EXPECT_NEAR(map.values(15, 40), 5.8333, 1e-9);
  EXPECT_EQ(map.values(0, 0), 0.0);
  EXPECT_THAT(chart.subtitle[0], HasSubstr("F_y = -350 N"));
  EXPECT_THAT(chart.subtitle[0], HasSubstr("F_r = 2 N toward 270°"));
  ASSERT_EQ(map.y_lines.size(), 1u);
  EXPECT_NEAR(map.y_lines[0].value, 270.0, 1e-9);
}

TEST(MakePressureChart, RefusesMismatchedSizes) {
  PressureMapData data = Data();
  data.interference.conservativeResize(10);
  EXPECT_THROW(MakePressureChart(data), UserError);
}

// A planar (key) grid: every strip of a face shares the face normal's angle, so the angles do not
// increase and the map numbers the columns face by face, as the skin-profile chart does.
PressureMapData FlatFaceData() {
  PressureMapData data = Data();
  data.grid = testing::SyntheticSms(testing::SyntheticPart("key", Role::kInner, 0.0, 20e-6, "h9"),
                                    30, 12, 30e-3, 0.0)
                  .grid;
  for (int j = 0; j < 12; ++j) data.grid.column_angle(j) = (j / 3) * 0.5 * std::numbers::pi;
  data.interference = Eigen::VectorXd::Zero(data.grid.size());
  data.interference(data.grid.index(5, 7)) = 2e-6;
  return data;
}

TEST(MakePressureChart, FlatFacesUseColumnNumbers) {
  const HeatMapChart chart = MakePressureChart(FlatFaceData());
  const HeatMap& map = chart.panels[0];
  EXPECT_EQ(map.y_label, "column (face by face)");
  ASSERT_EQ(map.y.size(), 12);
  for (int j = 0; j < 12; ++j) EXPECT_EQ(map.y(j), j);
  EXPECT_NEAR(map.values(5, 7), 2.0 * 5.8333, 1e-9);
  // No angle axis to draw the force's direction on; the subtitle still gives it.
  EXPECT_TRUE(map.y_lines.empty());
  EXPECT_THAT(chart.subtitle[0], HasSubstr("toward 270°"));
}

TEST(MakePressureChart, FlatFacesRender) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  Render(MakePressureChart(FlatFaceData()), ResolveOutputs(dir.path() / "key.png"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "key.png"));
}

TEST(MakePressureChart, SaysWhenThePartsAreInClearance) {
  PressureMapData data = Data();
  data.interference.setZero();
  EXPECT_THAT(MakePressureChart(data).subtitle.back(), HasSubstr("no interference at this pose"));
}

TEST(MakePressureChart, SaysHowThePoseWasTaken) {
  PressureMapData data = Data();
  EXPECT_EQ(MakePressureChart(data).subtitle.size(), 1u);
  data.pose_note = "offset from the device position";
  EXPECT_EQ(MakePressureChart(data).subtitle.back(), "offset from the device position");
}

TEST(MakePressureChart, RendersPngAndSvg) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  Render(MakePressureChart(Data()), ResolveOutputs(dir.path() / "pressure"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "pressure.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "pressure.svg"));
}

}  // namespace
}  // namespace fitfeel::plot
