#include "framework/plot/scene_charts.h"

#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plot/render.h"
#include "framework/plot/sms_chart.h"
#include "framework/plot/test/fake_laws.h"
#include "framework/plot/test/synthetic_sms.h"
#include "framework/plot/test/test_support.h"

namespace fitfeel::plot {
namespace {

using ::testing::HasSubstr;
using testing::kBushing;
using testing::kShaft;
using testing::LameLaw;
using testing::NoPressureLaw;
using testing::ScratchDir;

// Interference of 1 um on the shaft rows within `depth` of its leading end, and the pose asked.
class FakeAnalyzer final : public ContactAnalyzer {
 public:
  mutable MatingPose last_pose;
  int rows = 0, columns = 0;

 protected:
  void DoPrepare(const PartSpec&, const SkinModelShape& inner_sms, const PartSpec&,
                 const SkinModelShape&, const ModelSettings&) override {
    rows = inner_sms.grid.rows;
    columns = inner_sms.grid.columns;
  }
  void DoEvaluate(const MatingPose&, ContactState*) const noexcept override {}
  void DoInterferenceMap(const MatingPose& pose, Eigen::VectorXd* delta) const override {
    last_pose = pose;
    delta->setZero(rows * columns);
    const int engaged = static_cast<int>(pose.depth / 1e-3);
    for (int i = std::max(0, rows - engaged); i < rows; ++i) {
      for (int j = 0; j < columns; ++j) (*delta)(i * columns + j) = 1e-6;
    }
  }
};

TEST(MakeSceneSmsChart, BothPartsAndTheToleranceSpaceOrOnePart) {
  const auto shaft = testing::SyntheticSms(kShaft, 60, 72, 60e-3, 0.0);
  const auto bushing = testing::SyntheticSms(kBushing, 20, 72, 20e-3, 1.0);
  const HeatMapChart all = MakeSceneSmsChart("s", kShaft, shaft, kBushing, bushing, true);
  ASSERT_EQ(all.panels.size(), 3u);
  EXPECT_THAT(all.panels[2].title, HasSubstr("full insertion (depth 20 mm)"));
  const HeatMapChart one =
      MakeSceneSmsChart("s", kShaft, shaft, kBushing, bushing, true, "bushing");
  ASSERT_EQ(one.panels.size(), 1u);
  EXPECT_THAT(one.panels[0].title, HasSubstr("bushing"));
  try {
    MakeSceneSmsChart("s", kShaft, shaft, kBushing, bushing, true, "pin");
    FAIL() << "an unknown part was accepted";
  } catch (const UserError& e) {
    EXPECT_THAT(e.what(), HasSubstr("no part 'pin'; its parts are 'shaft' and 'bushing'"));
  }
}

RunRecord RunWithPose(const std::filesystem::path& dir) {
  std::string csv = "t_s,stage,depth_mm,fx_N,fy_N,fz_N,tick_us,x_mm,y_mm,z_mm,angle_rad\n";
  for (int k = 0; k <= 100; ++k) {
    csv += std::to_string(0.001 * k) + ",constrained," + std::to_string(0.2 * k) + ",0,-" +
           std::to_string(10 * k) + ",2,5,0.001,0,-0.002,0.01\n";
  }
  testing::WriteRun(dir, "paper-case1-h7js6", "gps", 1.0);
  testing::WriteFile(dir / "trace.csv", csv);
  return LoadRun(dir);
}

TEST(MakePressureData, UsesTheRunsPoseAndTheLawsCoefficient) {
  ScratchDir dir;
  const RunRecord run = RunWithPose(dir.path());
  const auto shaft = testing::SyntheticSms(kShaft, 60, 72, 60e-3, 0.0);
  const auto bushing = testing::SyntheticSms(kBushing, 20, 72, 20e-3, 1.0);
  FakeAnalyzer analyzer;
  analyzer.Prepare(kShaft, shaft, kBushing, bushing, ModelSettings{});
  const PressureMapData data = MakePressureData(run, 10.1, analyzer, LameLaw{}, shaft.grid);
  EXPECT_NEAR(analyzer.last_pose.depth, 10.1e-3, 1e-15);
  EXPECT_NEAR(analyzer.last_pose.offset.x(), 1e-6, 1e-15);
  EXPECT_NEAR(analyzer.last_pose.offset.y(), -2e-6, 1e-15);
  EXPECT_NEAR(analyzer.last_pose.angle, 0.01, 1e-15);
  EXPECT_DOUBLE_EQ(data.pressure_per_interference, 5.8333e12);
  EXPECT_DOUBLE_EQ(data.fy_N, -500.0);  // tick at 10.0 mm, the nearest to 10.1 mm
  EXPECT_DOUBLE_EQ(data.force_depth_mm, 10.0);
  const HeatMapChart chart = MakePressureChart(data);
  EXPECT_NEAR(chart.panels[0].values(59, 0), 5.8333, 1e-9);  // engaged leading row
  EXPECT_EQ(chart.panels[0].values(0, 0), 0.0);
}

// A trace with the pose's offset columns: the map is drawn at the pose's offset, not at the
// device's position (they differ where the constrained stage settled the part under a load).
TEST(MakePressureData, PrefersThePosesOffsetColumnsToTheDevicePosition) {
  ScratchDir dir;
  std::string csv =
      "t_s,stage,depth_mm,fx_N,fy_N,fz_N,tick_us,x_mm,y_mm,z_mm,angle_rad,offset_x_um,"
      "offset_z_um\n";
  for (int k = 0; k <= 100; ++k) {
    csv += std::to_string(0.001 * k) + ",constrained," + std::to_string(0.2 * k) + ",0,-" +
           std::to_string(10 * k) + ",2,5,0.001,0,-0.002,0.01,3.5,-4.25\n";
  }
  testing::WriteRun(dir.path(), "paper-case1-h7js6", "gps", 1.0);
  testing::WriteFile(dir.path() / "trace.csv", csv);
  const RunRecord run = LoadRun(dir.path());
  ASSERT_EQ(run.trace.offset_x_um.size(), 101u);
  const auto shaft = testing::SyntheticSms(kShaft, 60, 72, 60e-3, 0.0);
  FakeAnalyzer analyzer;
  analyzer.Prepare(kShaft, shaft, kBushing, shaft, ModelSettings{});
  const PressureMapData data = MakePressureData(run, 10.0, analyzer, LameLaw{}, shaft.grid);
  EXPECT_NEAR(analyzer.last_pose.offset.x(), 3.5e-6, 1e-15);
  EXPECT_NEAR(analyzer.last_pose.offset.y(), -4.25e-6, 1e-15);
  EXPECT_NEAR(analyzer.last_pose.angle, 0.01, 1e-15);
  EXPECT_TRUE(data.pose_note.empty());
  // With the outer part moving, the trace's pose is the bushing's in the scene frame: the
  // analyzer takes the shaft's in the bushing's, reflected in z (AnalyzerPose), and the force is
  // read there too, on the inner part whose map is drawn.
  const PressureMapData outer =
      MakePressureData(run, 10.0, analyzer, LameLaw{}, shaft.grid, Role::kOuter);
  EXPECT_NEAR(analyzer.last_pose.offset.x(), 3.5e-6, 1e-15);
  EXPECT_NEAR(analyzer.last_pose.offset.y(), 4.25e-6, 1e-15);
  EXPECT_NEAR(analyzer.last_pose.angle, 0.01, 1e-15);
  EXPECT_EQ(outer.fx_N, data.fx_N);
  EXPECT_EQ(outer.fy_N, data.fy_N);
  EXPECT_EQ(outer.fz_N, -data.fz_N);
  EXPECT_NE(data.fz_N, 0.0);
}

TEST(MakePressureData, AnOlderTraceFallsBackToTheDevicePositionAndSaysSo) {
  ScratchDir dir;
  const RunRecord run = RunWithPose(dir.path());
  EXPECT_TRUE(run.trace.offset_x_um.empty());
  const auto shaft = testing::SyntheticSms(kShaft, 60, 72, 60e-3, 0.0);
  FakeAnalyzer analyzer;
  analyzer.Prepare(kShaft, shaft, kBushing, shaft, ModelSettings{});
  const PressureMapData data = MakePressureData(run, 10.0, analyzer, LameLaw{}, shaft.grid);
  EXPECT_NEAR(analyzer.last_pose.offset.x(), 1e-6, 1e-15);
  EXPECT_THAT(data.pose_note, HasSubstr("taken from the device position (old trace"));
  EXPECT_THAT(MakePressureChart(data).subtitle.back(), HasSubstr("device position"));
}

TEST(MakePressureData, RefusesDepthOutsideTheRunAndLawsWithoutPressure) {
  ScratchDir dir;
  const RunRecord run = RunWithPose(dir.path());
  const auto shaft = testing::SyntheticSms(kShaft, 60, 72, 60e-3, 0.0);
  FakeAnalyzer analyzer;
  analyzer.Prepare(kShaft, shaft, kBushing, shaft, ModelSettings{});
  try {
    MakePressureData(run, 25.0, analyzer, LameLaw{}, shaft.grid);
    FAIL() << "a depth beyond the run was accepted";
  } catch (const UserError& e) {
    EXPECT_THAT(e.what(), HasSubstr("depth 25 mm is outside the run's constrained depth range"));
  }
  try {
    MakePressureData(run, 5.0, analyzer, NoPressureLaw{}, shaft.grid);
    FAIL() << "a law without pressure gave a map";
  } catch (const UnsupportedError& e) {
    EXPECT_THAT(e.what(), HasSubstr("its law 'gps' gives no contact pressure"));
  }
}

TEST(MakePressureData, RendersPngAndSvg) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  const RunRecord run = RunWithPose(dir.path() / "run");
  const auto shaft = testing::SyntheticSms(kShaft, 60, 72, 60e-3, 0.0);
  FakeAnalyzer analyzer;
  analyzer.Prepare(kShaft, shaft, kBushing, shaft, ModelSettings{});
  Render(MakePressureChart(MakePressureData(run, 12.0, analyzer, LameLaw{}, shaft.grid)),
         ResolveOutputs(dir.path() / "pressure"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "pressure.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "pressure.svg"));
}

}  // namespace
}  // namespace fitfeel::plot

namespace fitfeel::plot {
namespace {

// A key-like grid: four flat faces of three strips each, the strips of a face sharing its angle.
SkinModelShape FlatFaces(const PartSpec& part, int rows, double length, int strips) {
  SkinModelShape sms = testing::SyntheticSms(part, rows, 4 * strips, length, 0.0);
  for (int j = 0; j < 4 * strips; ++j)
    sms.grid.column_angle(j) = (j / strips) * 0.5 * std::numbers::pi;
  return sms;
}

TEST(MakeSceneSmsChart, RotationalMatingHasNoToleranceSpaceAndSaysWhy) {
  const auto ball = testing::SyntheticSms(kShaft, 20, 36, 20e-3, 0.0);
  const auto socket = testing::SyntheticSms(kBushing, 20, 36, 20e-3, 1.0);
  const HeatMapChart chart = MakeSceneSmsChart("s", kShaft, ball, kBushing, socket, false);
  EXPECT_EQ(chart.panels.size(), 2u);
  EXPECT_THAT(chart.subtitle.back(), HasSubstr("mate by rotation"));
}

TEST(MakeSceneSmsChart, FlatFacesUseColumnNumbersAndFaceOneToOne) {
  const auto key = FlatFaces(kShaft, 30, 30e-3, 3);
  const auto keyway = FlatFaces(kBushing, 10, 10e-3, 3);
  const HeatMapChart chart = MakeSceneSmsChart("key", kShaft, key, kBushing, keyway, true);
  ASSERT_EQ(chart.panels.size(), 3u);
  EXPECT_EQ(chart.panels[0].y_label, "column (face by face)");
  EXPECT_EQ(chart.panels[0].y(11), 11.0);
  const ToleranceSpaceGrid space = ToleranceSpaceAtDepth(key, keyway, 10e-3, 1);
  // Column 4 (second face, second strip) faces column 4: at 0.5 mm in, key row 20 and keyway row 0.
  EXPECT_NEAR(space.value(0, 4), keyway.variation(4) - key.variation(20 * 12 + 4), 1e-15);

  const auto other = FlatFaces(kBushing, 10, 10e-3, 2);  // a different face split
  const HeatMapChart partial = MakeSceneSmsChart("key", kShaft, key, kBushing, other, true);
  EXPECT_EQ(partial.panels.size(), 2u);
  EXPECT_THAT(partial.subtitle.back(), HasSubstr("columns do not face each other"));
}

TEST(MakeSceneSmsChart, FlatFacesRender) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  const auto key = FlatFaces(kShaft, 30, 30e-3, 3);
  const auto keyway = FlatFaces(kBushing, 10, 10e-3, 3);
  Render(MakeSceneSmsChart("key", kShaft, key, kBushing, keyway, true),
         ResolveOutputs(dir.path() / "key.png"));
  EXPECT_TRUE(testing::IsPng(dir.path() / "key.png"));
}

}  // namespace
}  // namespace fitfeel::plot
