#include "framework/plot/run_record.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plot/test/test_support.h"

namespace fitfeel::plot {
namespace {

using ::testing::HasSubstr;
using testing::ScratchDir;
using testing::WriteFile;

std::string MessageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const UserError& e) {
    return e.what();
  }
  return "(no UserError thrown)";
}

TEST(LoadRun, ReadsSummaryAndOnlyConstrainedRows) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "run", "paper-case1-h7js6", "gps", 12.0, 200);
  const RunRecord run = LoadRun(dir.path() / "run");
  EXPECT_EQ(run.summary.scenario, "paper-case1-h7js6");
  EXPECT_EQ(run.summary.law, "gps");
  EXPECT_EQ(run.summary.seed, 1u);
  EXPECT_EQ(run.summary.scenario_file, "scenarios/paper-case1-h7js6.yaml");
  EXPECT_DOUBLE_EQ(run.summary.axial.mean, 12.0);
  EXPECT_DOUBLE_EQ(run.summary.axial.max, 13.2);
  EXPECT_EQ(run.trace.depth_mm.size(), 180u);
  EXPECT_DOUBLE_EQ(run.trace.depth_mm.front(), 0.0);
  EXPECT_NEAR(run.trace.depth_mm.back(), 17.9, 1e-9);
  EXPECT_DOUBLE_EQ(run.trace.fz_N.front(), 2.0);
}

TEST(LoadSummary, ReadsTheRecordedGrids) {
  ScratchDir dir;
  const auto file = dir.path() / "summary.json";
  const std::string stats = "{\"mean\": 1, \"min\": 0, \"max\": 2}";
  WriteFile(file, "{\"scenario\": \"s\", \"axial_resistance_N\": " + stats +
                      ", \"radial_resistance_N\": " + stats +
                      ", \"grid\": {\"inner\": {\"rows\": 40, \"columns\": 360}, "
                      "\"outer\": {\"rows\": 20, \"columns\": 360}}}");
  const RunSummary summary = LoadSummary(file);
  EXPECT_EQ(summary.inner_grid, std::make_pair(40, 360));
  EXPECT_EQ(summary.outer_grid, std::make_pair(20, 360));
  EXPECT_TRUE(summary.law.empty());
}

TEST(LoadConstrainedTrace, ReadsTheTorqueWhereTheTraceHasIt) {
  ScratchDir dir;
  WriteFile(dir.path() / "trace.csv",
            "t_s,stage,depth_mm,fx_N,fy_N,fz_N,tx_Nm,ty_Nm,tz_Nm\n"
            "0,positioning,-1,0,0,0,0,0,0\n"
            "0.001,constrained,0.5,1,-2,3,0.1,-5,0.3\n");
  const ConstrainedTrace trace = LoadConstrainedTrace(dir.path() / "trace.csv");
  ASSERT_EQ(trace.ty_Nm.size(), 1u);
  EXPECT_DOUBLE_EQ(trace.tx_Nm[0], 0.1);
  EXPECT_DOUBLE_EQ(trace.ty_Nm[0], -5.0);
  EXPECT_DOUBLE_EQ(trace.tz_Nm[0], 0.3);
  WriteFile(dir.path() / "trace.csv",
            "t_s,stage,depth_mm,fx_N,fy_N,fz_N\n0.001,constrained,0.5,1,-2,3\n");
  EXPECT_TRUE(LoadConstrainedTrace(dir.path() / "trace.csv").ty_Nm.empty());
}

TEST(LoadRun, MissingFolderIsRefused) {
  ScratchDir dir;
  EXPECT_THAT(MessageOf([&] { LoadRun(dir.path() / "absent"); }), HasSubstr("does not exist"));
}

TEST(LoadRun, FolderWithoutTraceIsRefused) {
  ScratchDir dir;
  testing::WriteRun(dir.path(), "s", "gps", 1.0);
  std::filesystem::remove(dir.path() / "trace.csv");
  EXPECT_THAT(MessageOf([&] { LoadRun(dir.path()); }), HasSubstr("has no trace.csv"));
}

TEST(LoadConstrainedTrace, MissingColumnsAreNamed) {
  ScratchDir dir;
  WriteFile(dir.path() / "trace.csv", "t_s,stage,depth_mm,fx_N\n0,constrained,0,1\n");
  const std::string message = MessageOf([&] { LoadConstrainedTrace(dir.path() / "trace.csv"); });
  EXPECT_THAT(message, HasSubstr("trace.csv:1: header lacks the column(s) fy_N, fz_N"));
}

TEST(LoadConstrainedTrace, BadNumberNamesLineColumnAndField) {
  ScratchDir dir;
  WriteFile(dir.path() / "trace.csv",
            "t_s,stage,depth_mm,fx_N,fy_N,fz_N,tick_us\n"
            "0,constrained,0,0,1,0,5\n"
            "0.001,constrained,0.01,0,abc,0,5\n");
  EXPECT_THAT(MessageOf([&] { LoadConstrainedTrace(dir.path() / "trace.csv"); }),
              HasSubstr("trace.csv:3:26: fy_N: expected a number, found 'abc'"));
}

TEST(LoadConstrainedTrace, ShortRowIsRefused) {
  ScratchDir dir;
  WriteFile(dir.path() / "trace.csv",
            "t_s,stage,depth_mm,fx_N,fy_N,fz_N,tick_us\n0,constrained,0,0,1\n");
  EXPECT_THAT(MessageOf([&] { LoadConstrainedTrace(dir.path() / "trace.csv"); }),
              HasSubstr("trace.csv:2: expected 7 fields"));
}

TEST(LoadConstrainedTrace, NoConstrainedRowIsRefused) {
  ScratchDir dir;
  WriteFile(dir.path() / "trace.csv",
            "t_s,stage,depth_mm,fx_N,fy_N,fz_N,tick_us\n0,positioning,0,0,0,0,5\n");
  EXPECT_THAT(MessageOf([&] { LoadConstrainedTrace(dir.path() / "trace.csv"); }),
              HasSubstr("no row in the constrained stage"));
}

TEST(LoadSummary, MissingOrMalformedKeysAreNamed) {
  ScratchDir dir;
  const auto file = dir.path() / "summary.json";
  WriteFile(file, "{\"scenario\": \"s\", \"axial_resistance_N\": {\"mean\": 1, \"min\": 0}}");
  EXPECT_THAT(MessageOf([&] { LoadSummary(file); }), HasSubstr("axial_resistance_N.max"));
  WriteFile(file, "{\"axial_resistance_N\": {}}");
  EXPECT_THAT(MessageOf([&] { LoadSummary(file); }), HasSubstr("scenario: expected a value"));
  WriteFile(file, "{\"scenario\": 3}");
  EXPECT_THAT(MessageOf([&] { LoadSummary(file); }), HasSubstr("expected a string, found 3"));
  WriteFile(file, "{not json");
  EXPECT_THAT(MessageOf([&] { LoadSummary(file); }), HasSubstr("not valid JSON"));
}

}  // namespace
}  // namespace fitfeel::plot
