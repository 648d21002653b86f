#include "framework/model/column_response_table.h"

#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

// A column of `n` cells with gaps spread over +-spread, cosines in [cos_min, 1].
std::vector<ColumnCell> RandomColumn(std::mt19937_64& rng, int n, double spread, double cos_min) {
  std::uniform_real_distribution<double> gap(-spread, spread), cosine(cos_min, 1.0),
      area(0.5e-6, 1.5e-6);
  std::vector<ColumnCell> cells;
  for (int i = 0; i < n; ++i) cells.push_back({area(rng), cosine(rng), gap(rng)});
  return cells;
}

ExpectedInterferenceTable Texture(double limit) {
  if (limit == 0.0) return {};
  return ExpectedInterferenceTable(TruncatedGaussian{0.0, limit / 3.0, -limit, limit});
}

// Tabulated == cell by cell within the stated bound, for sharp and rough contacts, equal and
// unequal cosines, everywhere from no contact to deep interference (tails included).
TEST(ColumnResponseTable, AgreesWithTheCellSumWithinItsBound) {
  std::mt19937_64 rng(7);
  for (double limit : {0.0, 2e-6, 6e-6}) {
    const ExpectedInterferenceTable texture = Texture(limit);
    for (double cos_min : {1.0, 0.9}) {
      ColumnResponseTable table(4, 5, 33, texture);
      std::vector<std::vector<ColumnCell>> columns;
      for (int e = 0; e < 20; ++e) {
        columns.push_back(RandomColumn(rng, 1 + e % 12, 10e-6, cos_min));
        table.Fill(e / 5, e % 5, columns.back());
      }
      std::uniform_real_distribution<double> x(-30e-6, 30e-6);
      for (int e = 0; e < 20; ++e) {
        const double bound = table.VolumeErrorBound(e / 5, e % 5);
        for (int trial = 0; trial < 200; ++trial) {
          const double at = x(rng);
          const ColumnResponse exact = ColumnResponseTable::Exact(columns[e], texture, at);
          const ColumnResponse got = table.At(e / 5, e % 5, at);
          EXPECT_NEAR(got.volume, exact.volume, bound + 1e-12 * exact.volume) << limit << " " << at;
          EXPECT_NEAR(got.resultant, exact.resultant, bound + 1e-12 * exact.volume);
          if (cos_min == 1.0 && at > 20e-6) {
            EXPECT_NEAR(got.max, exact.max, 1e-18 + 1e-12 * at);
          }
        }
      }
    }
  }
}

TEST(ColumnResponseTable, BoundShrinksWithTheSquareOfTheSpacingForARoughContact) {
  std::mt19937_64 rng(3);
  const ExpectedInterferenceTable texture = Texture(6e-6);
  const std::vector<ColumnCell> cells = RandomColumn(rng, 10, 10e-6, 0.9);
  ColumnResponseTable coarse(1, 1, 17, texture), fine(1, 1, 33, texture);
  coarse.Fill(0, 0, cells);
  fine.Fill(0, 0, cells);
  EXPECT_NEAR(fine.VolumeErrorBound(0, 0) / coarse.VolumeErrorBound(0, 0), 0.25, 1e-9);
}

TEST(ColumnResponseTable, IsNondecreasingAndContinuousInTheOffset) {
  std::mt19937_64 rng(11);
  const ExpectedInterferenceTable texture = Texture(3e-6);
  ColumnResponseTable table(1, 1, 33, texture);
  const std::vector<ColumnCell> cells = RandomColumn(rng, 8, 5e-6, 0.9);
  table.Fill(0, 0, cells);
  double previous = 0.0;
  const double dx = 1e-10;
  for (double at = -20e-6; at < 20e-6; at += dx) {
    const double v = table.At(0, 0, at).volume;
    EXPECT_GE(v, previous);
    // Slope at most sum area * cosine.
    EXPECT_LE(v - previous, dx * 1.5e-6 * 8 + 1e-24);
    previous = v;
  }
}

TEST(ColumnResponseTable, AnEmptyColumnTouchesNothing) {
  ColumnResponseTable table(1, 1, 9, ExpectedInterferenceTable());
  table.Fill(0, 0, {});
  const ColumnResponse r = table.At(0, 0, 1.0);
  EXPECT_EQ(r.volume, 0.0);
  EXPECT_EQ(r.resultant, 0.0);
  EXPECT_EQ(r.max, 0.0);
}

TEST(ColumnResponseTable, RefusesBadShapesAndCosines) {
  EXPECT_THROW(ColumnResponseTable(1, 1, 1, ExpectedInterferenceTable()), std::invalid_argument);
  EXPECT_THROW(ColumnResponseTable(0, 1, 9, ExpectedInterferenceTable()), std::invalid_argument);
  ColumnResponseTable table(1, 1, 9, ExpectedInterferenceTable());
  const std::vector<ColumnCell> bad{{1e-6, 0.0, 0.0}};
  EXPECT_THROW(table.Fill(0, 0, bad), std::invalid_argument);
}

}  // namespace
}  // namespace fitfeel
