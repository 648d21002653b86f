#include "framework/plot/trace_chart.h"

#include <algorithm>
#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plot/render.h"
#include "framework/plot/test/test_support.h"

namespace fitfeel::plot {
namespace {

using ::testing::HasSubstr;
using testing::ScratchDir;

TEST(DecimateKeepingPeaks, KeepsEveryPeakAndOrder) {
  std::vector<double> x, y;
  for (int k = 0; k < 100000; ++k) {
    x.push_back(k);
    y.push_back(std::sin(0.001 * k));
  }
  y[31234] = 50.0;
  y[77777] = -40.0;
  DecimateKeepingPeaks(&x, &y, 1000);
  EXPECT_LE(x.size(), 1000u);
  EXPECT_EQ(*std::max_element(y.begin(), y.end()), 50.0);
  EXPECT_EQ(*std::min_element(y.begin(), y.end()), -40.0);
  EXPECT_TRUE(std::is_sorted(x.begin(), x.end()));
}

TEST(DecimateKeepingPeaks, ShortCurvesAreUntouched) {
  std::vector<double> x = {1, 2, 3}, y = {4, 5, 6};
  DecimateKeepingPeaks(&x, &y, 1000);
  EXPECT_EQ(y, (std::vector<double>{4, 5, 6}));
}

TEST(FormatNewtons, PrecisionFollowsMagnitude) {
  EXPECT_EQ(FormatNewtons(1099.6), "1100 N");
  EXPECT_EQ(FormatNewtons(12.345), "12.3 N");
  EXPECT_EQ(FormatNewtons(0.3), "0.3 N");
  EXPECT_EQ(FormatNewtons(0.00010023), "0.0001 N");
  EXPECT_EQ(FormatNewtons(588.36), "588 N");
  EXPECT_EQ(FormatNewtons(-2.5), "-2.5 N");
  EXPECT_EQ(FormatNewtons(999.99), "1000 N");  // not 1e+03 N
  EXPECT_EQ(FormatNewtons(-0.0), "0 N");
}

TEST(MakeTraceChart, OneLabelledCurvePerRunInEachPanel) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "a", "paper-case1-h7js6", "gps", 12.0);
  testing::WriteRun(dir.path() / "b", "paper-case1-h7g6", "ve1", 3.0);
  const LineChart chart = MakeTraceChart({LoadRun(dir.path() / "a"), LoadRun(dir.path() / "b")});
  ASSERT_EQ(chart.panels.size(), 2u);
  for (const auto& panel : chart.panels) {
    ASSERT_EQ(panel.series.size(), 2u);
    EXPECT_THAT(panel.x_label, HasSubstr("(mm)"));
    EXPECT_THAT(panel.y_label, HasSubstr("(N)"));
  }
  EXPECT_THAT(chart.panels[0].series[0].label, HasSubstr("paper-case1-h7js6 · law gps"));
  EXPECT_THAT(chart.panels[0].series[0].label, HasSubstr("mean 12 N, min 10.8 N, max 13.2 N"));
  EXPECT_THAT(chart.panels[1].series[1].label, HasSubstr("paper-case1-h7g6 · law ve1"));
  // Axial panel plots |fy|; radial plots hypot(fx, fz) = hypot(0.5, 2).
  const auto& axial = chart.panels[0].series[0].y;
  EXPECT_TRUE(std::all_of(axial.begin(), axial.end(), [](double v) { return v > 0.0; }));
  EXPECT_NEAR(chart.panels[1].series[0].y.front(), std::hypot(0.5, 2.0), 1e-12);
  EXPECT_EQ(chart.panels[0].series[0].x.size(), 180u);
}

// A knuckle bearing turns at one depth: its curves are drawn against time.
TEST(MakeTraceChart, RunsAtOneDepthAreDrawnAgainstTime) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "a", "knuckle-bearing", "gps", 1000.0);
  std::string csv = "t_s,stage,depth_mm,fx_N,fy_N,fz_N\n";
  for (int k = 0; k < 50; ++k) {
    csv += std::to_string(0.001 * k) + ",constrained,0," + std::to_string(k) + ",0,1000\n";
  }
  testing::WriteFile(dir.path() / "a" / "trace.csv", csv);
  const LineChart chart = MakeTraceChart({LoadRun(dir.path() / "a")});
  EXPECT_EQ(chart.panels[0].x_label, "time (s)");
  EXPECT_THAT(chart.title, HasSubstr("against time"));
  EXPECT_NEAR(chart.panels[1].series[0].x.back(), 0.049, 1e-12);
  EXPECT_NEAR(chart.panels[1].series[0].y.back(), std::hypot(49.0, 1000.0), 1e-9);
}

TEST(MakeTraceChart, NoRunIsRefused) { EXPECT_THROW(MakeTraceChart({}), UserError); }

// A screw's run: torque and preload against the turn angle in degrees, labelled with where the
// run ended.
TEST(MakeTorqueChart, TorqueAndPreloadAgainstTheTurnAngle) {
  ScratchDir dir;
  testing::WriteScrewRun(dir.path() / "bolt");
  const LineChart chart = MakeTorqueChart({LoadRun(dir.path() / "bolt")});
  ASSERT_EQ(chart.panels.size(), 2u);
  const Series& torque = chart.panels[0].series.at(0);
  const Series& preload = chart.panels[1].series.at(0);
  EXPECT_EQ(chart.panels[0].x_label, "turn angle (deg)");
  EXPECT_THAT(chart.panels[0].y_label, HasSubstr("(N·m)"));
  EXPECT_THAT(chart.panels[1].y_label, HasSubstr("(N)"));
  ASSERT_EQ(torque.x.size(), 180u);
  // The last constrained tick (199): turned 17.9 rad, 0.01 + 0.4 * 99 N*m, 1 kN per N*m.
  EXPECT_NEAR(torque.x.back(), 17.9 * 180.0 / M_PI, 1e-3);
  EXPECT_NEAR(torque.y.back(), 39.61, 1e-9);
  EXPECT_NEAR(preload.y.back(), 39610.0, 1e-6);
  EXPECT_EQ(preload.x, torque.x);
  EXPECT_THAT(torque.label, HasSubstr("bolt-m10 · law flank: 39.6 N·m at the end"));
  EXPECT_THAT(preload.label, HasSubstr("39610 N at the end"));
}

// A run whose nut met the face: the angle counts from the meeting (row 100, 8.0 rad) and the chart
// starts a quarter turn before it.
TEST(MakeTorqueChart, CountsTheAngleFromTheFacesMeeting) {
  ScratchDir dir;
  testing::WriteScrewRun(dir.path() / "bolt", 200, true);
  const LineChart chart = MakeTorqueChart({LoadRun(dir.path() / "bolt")});
  const Series& torque = chart.panels[0].series.at(0);
  EXPECT_EQ(chart.panels[0].x_label, "turn past the bearing face's meeting (deg)");
  EXPECT_GE(torque.x.front(), -90.0);
  EXPECT_LT(torque.x.front(), -90.0 + 0.1 * 180.0 / M_PI);
  EXPECT_NEAR(torque.x.back(), (17.9 - 8.0) * 180.0 / M_PI, 1e-3);
}

TEST(MakeTorqueChart, RefusesARunThatIsNoScrews) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "fit", "paper-case1-h7js6", "gps", 12.0);
  try {
    MakeTorqueChart({LoadRun(dir.path() / "fit")});
    FAIL() << "a fit's run drawn as a screw's";
  } catch (const UserError& e) {
    EXPECT_THAT(e.what(), HasSubstr("has no torque_Nm"));
  }
  EXPECT_THROW(MakeTorqueChart({}), UserError);
}

TEST(MakeTraceChart, RendersThreeRunsToPngAndSvg) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  testing::WriteRun(dir.path() / "a", "paper-case1-h7js6", "gps", 12.0);
  testing::WriteRun(dir.path() / "b", "paper-case1-h7g6", "gps", 3.0);
  testing::WriteRun(dir.path() / "c", "paper-case1-h7js6", "ve1", 1.0);
  const auto chart = MakeTraceChart(
      {LoadRun(dir.path() / "a"), LoadRun(dir.path() / "b"), LoadRun(dir.path() / "c")});
  Render(chart, ResolveOutputs(dir.path() / "trace"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "trace.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "trace.svg"));
}

}  // namespace
}  // namespace fitfeel::plot
