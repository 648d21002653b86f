#include "framework/tradeoff/tradeoff_study.h"

#include <cmath>
#include <limits>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace fitfeel::tradeoff {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

RunSample Sample(int rows, int columns, std::vector<double> fy, double p50 = 1.0) {
  RunSample s;
  s.inner_rows = s.outer_rows = rows;
  s.inner_columns = s.outer_columns = columns;
  s.prepare_seconds = 0.01 * rows;
  s.tick_p50_us = p50;
  s.tick_p99_us = 2.0 * p50;
  s.fy = std::move(fy);
  return s;
}

// Two grids given fine first: the summary sorts coarse to fine and takes the finest as the
// reference; every statistic below is worked by hand.
TEST(TradeoffStudy, SummarizesAgainstTheFinestGrid) {
  // Fine grid: seeds give traces {NaN, 10, 10} and {NaN, 12, 14}.
  const std::vector<RunSample> fine = {Sample(40, 360, {kNaN, 10.0, 10.0}, 5.0),
                                       Sample(40, 360, {kNaN, 12.0, 14.0}, 7.0)};
  // Coarse grid: {NaN, 8, -6} and {3, 10, -10}; tick 0 is not constrained in every run.
  const std::vector<RunSample> coarse = {Sample(8, 36, {kNaN, 8.0, -6.0}, 1.0),
                                         Sample(8, 36, {3.0, 10.0, -10.0}, 3.0)};
  const std::vector<GridRow> rows = Summarize({"40x360", "8x36"}, {fine, coarse});
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].label, "8x36");
  EXPECT_EQ(rows[0].inner_cells, 288);
  EXPECT_FALSE(rows[0].reference);
  EXPECT_EQ(rows[1].label, "40x360");
  EXPECT_TRUE(rows[1].reference);

  // Means of |fy| per run: fine 10 and 13 -> 11.5, SD sqrt(4.5); coarse 7 and 23/3.
  EXPECT_DOUBLE_EQ(rows[1].mean_axial_N, 11.5);
  EXPECT_NEAR(rows[1].sd_axial_N, std::sqrt(4.5), 1e-12);
  EXPECT_NEAR(rows[1].se_axial_N, std::sqrt(4.5) / std::sqrt(2.0), 1e-12);
  const double coarse_mean = (7.0 + 23.0 / 3.0) / 2.0;
  EXPECT_NEAR(rows[0].mean_axial_N, coarse_mean, 1e-12);
  EXPECT_NEAR(rows[0].bias_N, coarse_mean - 11.5, 1e-12);
  EXPECT_DOUBLE_EQ(rows[1].bias_N, 0.0);
  EXPECT_DOUBLE_EQ(rows[0].tick_p50_us, 2.0);  // median of 1 and 3
  EXPECT_DOUBLE_EQ(rows[0].tick_p99_us, 4.0);

  // Seed-mean traces on ticks 1, 2: coarse {9, -8}, fine {11, 12}: differences 2 and 20.
  EXPECT_EQ(rows[0].compared_ticks, 2);
  EXPECT_NEAR(rows[0].rms_error_N, std::sqrt((4.0 + 400.0) / 2.0), 1e-12);
  EXPECT_DOUBLE_EQ(rows[0].max_error_N, 20.0);
  EXPECT_NEAR(rows[0].rms_error_rel, rows[0].rms_error_N / 11.5, 1e-12);
  EXPECT_NEAR(rows[0].max_error_rel, 20.0 / 11.5, 1e-12);
  // Paired differences coarse - fine: tick 1 {-2, -2} (variance 0), tick 2 {-16, -24} (sample
  // variance 32, of the mean 16).
  EXPECT_NEAR(rows[0].noise_rms_N, std::sqrt((0.0 + 16.0) / 2.0), 1e-12);
  // Run means coarse - fine: 7 - 10 and 23/3 - 13: sample SD of {-3, -16/3} over sqrt(2).
  EXPECT_NEAR(rows[0].bias_se_N, std::abs(-3.0 + 16.0 / 3.0) / std::sqrt(2.0) / std::sqrt(2.0),
              1e-12);
  EXPECT_DOUBLE_EQ(rows[1].rms_error_N, 0.0);
  EXPECT_DOUBLE_EQ(rows[1].noise_rms_N, 0.0);
}

TEST(TradeoffStudy, RejectsRunsThatCannotBeCompared) {
  EXPECT_THROW(Summarize({}, {}), UserError);
  // Different numbers of seeds.
  EXPECT_THROW(Summarize({"a", "b"},
                         {{Sample(8, 36, {1.0})}, {Sample(16, 72, {1.0}), Sample(16, 72, {2.0})}}),
               UserError);
  // A run that never reached the constrained stage.
  EXPECT_THROW(Summarize({"a"}, {{Sample(8, 36, {kNaN, kNaN})}}), UserError);
  // Constrained ticks that never coincide.
  EXPECT_THROW(Summarize({"a", "b"}, {{Sample(8, 36, {1.0, kNaN})}, {Sample(16, 72, {kNaN, 1.0})}}),
               UserError);
}

TEST(TradeoffStudy, ReadsConstrainedFyFromATrace) {
  const std::vector<double> fy = ConstrainedFy(
      "t_s,stage,depth_mm,fx_N,fy_N,fz_N\n0,positioning,0,0,0.5,0\n0.001,constrained,1,0,-2.25,"
      "0\n");
  ASSERT_EQ(fy.size(), 2u);
  EXPECT_TRUE(std::isnan(fy[0]));
  EXPECT_DOUBLE_EQ(fy[1], -2.25);
  EXPECT_THROW(ConstrainedFy("t_s,depth_mm\n0,0\n"), std::runtime_error);
  EXPECT_THROW(ConstrainedFy("stage,fy_N\nconstrained,abc\n"), std::runtime_error);
}

TEST(TradeoffStudy, CsvHasAHeaderAndOneLinePerGrid) {
  const std::vector<GridRow> rows =
      Summarize({"8x36", "16x72"}, {{Sample(8, 36, {1.0, 2.0})}, {Sample(16, 72, {1.0, 3.0})}});
  std::istringstream in(TradeoffCsv(rows));
  std::string header, a, b, extra;
  std::getline(in, header);
  std::getline(in, a);
  std::getline(in, b);
  EXPECT_FALSE(std::getline(in, extra));
  EXPECT_EQ(header.rfind("grid,inner_rows,inner_columns", 0), 0u);
  EXPECT_EQ(a.rfind("8x36,8,36,8,36,288,288,1,", 0), 0u);
  EXPECT_NE(b.find(",yes"), std::string::npos);
}

}  // namespace
}  // namespace fitfeel::tradeoff
