#include "framework/plot/render.h"

#include <cmath>

#include <gtest/gtest.h>

#include "framework/plot/test/test_support.h"

namespace fitfeel::plot {
namespace {

namespace fs = std::filesystem;
using testing::ScratchDir;

LineChart TwoPanelChart() {
  LineChart chart;
  chart.title = "synthetic";
  for (int p = 0; p < 2; ++p) {
    LinePanel panel{"panel " + std::to_string(p), "depth (mm)", "force (N)", true, p == 1, {}};
    for (int s = 0; s < 3; ++s) {
      Series series{"run " + std::to_string(s), {}, {}};
      for (int k = 0; k < 100; ++k) {
        series.x.push_back(0.2 * k);
        series.y.push_back((s + 1) * (1.0 + std::sin(0.1 * k + p)));
      }
      series.y[50] = std::nan("");  // a gap
      panel.series.push_back(series);
    }
    chart.panels.push_back(panel);
  }
  return chart;
}

HeatMap SyntheticMap(int nx, int ny, bool regular) {
  HeatMap map;
  map.title = "synthetic map";
  map.x_label = "axial position (mm)";
  map.y_label = "angle (°)";
  map.colour_label = "V (µm)";
  map.x.resize(nx);
  map.y.resize(ny);
  for (int i = 0; i < nx; ++i) map.x(i) = regular ? 0.5 * i : 0.5 * i + 0.01 * i * i;
  for (int j = 0; j < ny; ++j) map.y(j) = (j + 0.5) * 360.0 / ny;
  map.values.resize(nx, ny);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) map.values(i, j) = 3.0 * std::sin(0.2 * i) * std::cos(0.1 * j);
  }
  map.colour_min = -4.0;
  map.colour_max = 4.0;
  map.colour_marks = {{-4.0, "lower limit −4 µm"}, {4.0, "upper limit +4 µm"}};
  map.y_tic_step = 90.0;
  return map;
}

TEST(Render, LineChartWritesPngAndSvg) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  Render(TwoPanelChart(), ResolveOutputs(dir.path() / "lines"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "lines.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "lines.svg"));
}

TEST(Render, RegularHeatMapWritesPngAndSvg) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  HeatMapChart chart{
      "maps", {"subtitle line"}, {SyntheticMap(40, 72, true), SyntheticMap(20, 36, true)}};
  Render(chart, ResolveOutputs(dir.path() / "maps"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "maps.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "maps.svg"));
  // The colour bar carries the tolerance limits as labelled tics.
  EXPECT_NE(testing::ReadFile(dir.path() / "maps.svg").find("upper limit +4 µm"),
            std::string::npos);
}

TEST(Render, IrregularHeatMapWritesPng) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  HeatMapChart chart{"uneven cells", {}, {SyntheticMap(15, 8, false)}};
  Render(chart, ResolveOutputs(dir.path() / "uneven.png"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "uneven.png"));
}

TEST(Render, ConstantMapGetsAUsableColourRange) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  HeatMap map = SyntheticMap(10, 12, true);
  map.values.setZero();
  map.colour_min = 0.0;
  map.colour_max.reset();
  map.colour_marks.clear();
  Render(HeatMapChart{"no contact", {}, {map}}, ResolveOutputs(dir.path() / "zero.png"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "zero.png"));
}

TEST(Render, FlatAndZeroCurvesRenderOnLinearAndLogAxes) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  LineChart chart;
  chart.title = "flat";
  chart.panels.push_back(
      {"constant, log", "x (mm)", "y (N)", true, true, {{"c", {0, 1, 2}, {2, 2, 2}}}});
  chart.panels.push_back(
      {"zero, from 0", "x (mm)", "y (N)", true, false, {{"z", {0, 1, 2}, {0, 0, 0}}}});
  chart.panels.push_back(
      {"constant", "x (mm)", "y (N)", false, false, {{"c", {0, 1, 2}, {-3, -3, -3}}}});
  Render(chart, ResolveOutputs(dir.path() / "flat.png"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "flat.png"));
}

// A run in clearance throughout (`fitfeel plot trace --log` of a loose key) has only zeros: a log
// axis cannot show them, so the series stays in the key only, alone or beside others.
TEST(Render, AllZeroCurvesOnALogAxisStayInTheKey) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  LineChart chart;
  chart.title = "zero on log";
  chart.panels.push_back(
      {"beside another, log",
       "x (mm)",
       "y (N)",
       true,
       true,
       {{"some", {0, 1, 2}, {1, 10, 100}},
        {"key-parallel-8x7-hub-js9 · law gps: mean 0 N, min 0 N, max 0 N", {0, 1, 3}, {0, 0, 0}}}});
  chart.panels.push_back(
      {"alone, log", "x (mm)", "y (N)", true, true, {{"zero", {0, 1, 2}, {0, 0, 0}}}});
  Render(chart, ResolveOutputs(dir.path() / "zero.png"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "zero.png"));
}

TEST(Render, MalformedDataIsRefusedBeforeGnuplotRuns) {
  ScratchDir dir;
  const auto out = ResolveOutputs(dir.path() / "x.png");
  EXPECT_THROW(Render(LineChart{}, out), std::invalid_argument);
  LineChart mismatched = TwoPanelChart();
  mismatched.panels[0].series[0].y.pop_back();
  EXPECT_THROW(Render(mismatched, out), std::invalid_argument);
  HeatMap map = SyntheticMap(5, 5, true);
  map.values(2, 2) = std::nan("");
  EXPECT_THROW(Render(HeatMapChart{"t", {}, {map}}, out), std::invalid_argument);
  map = SyntheticMap(5, 5, true);
  map.x(3) = map.x(2);
  EXPECT_THROW(Render(HeatMapChart{"t", {}, {map}}, out), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir.path() / "x.png"));
}

TEST(Render, FailureLeavesAnExistingFileUntouched) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  testing::WriteFile(dir.path() / "keep.png", "previous");
  testing::ScopedEnv env("FITFEEL_GNUPLOT", "/nonexistent/gnuplot");
  EXPECT_ANY_THROW(Render(TwoPanelChart(), ResolveOutputs(dir.path() / "keep.png")));
  EXPECT_EQ(testing::ReadFile(dir.path() / "keep.png"), "previous");
}

}  // namespace
}  // namespace fitfeel::plot
