#include "surfaces/common/column_response_table.h"

#include <cmath>
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

// The blend's resultant Jacobian is the derivative of the blended resultant: against central
// differences over 1 pm at 2000 random offsets (sharp and rough contacts, 24 columns around, two
// steps blended), wherever no column's piece changes within the difference (the interpolation
// is piecewise linear, so there the difference is exact to rounding).
TEST(ColumnResponseTable, BlendsTheResultantsJacobian) {
  std::mt19937_64 rng(11);
  constexpr int kColumns = 24;
  Eigen::Matrix2Xd directions(2, kColumns);
  for (int j = 0; j < kColumns; ++j) {
    const double angle = 2.0 * M_PI * j / kColumns;
    directions.col(j) = Eigen::Vector2d(std::cos(angle), std::sin(angle));
  }
  std::uniform_real_distribution<double> offset(-12e-6, 12e-6), weight(0.0, 1.0);
  int compared = 0;
  for (double limit : {0.0, 4e-6}) {
    ColumnResponseTable table(2, kColumns, 33, Texture(limit));
    for (int k = 0; k < 2; ++k) {
      for (int j = 0; j < kColumns; ++j) table.Fill(k, j, RandomColumn(rng, 6, 8e-6, 0.9));
    }
    for (int trial = 0; trial < 1000; ++trial) {
      const Eigen::Vector2d e(offset(rng), offset(rng));
      const double t = weight(rng);
      ContactState at;
      table.Blend(0, 1, t, directions, e, 1e-6, &at);
      if (!at.interference) continue;
      constexpr double h = 1e-12;
      Eigen::Matrix2d numeric;
      bool smooth = true;
      for (int axis = 0; axis < 2; ++axis) {
        ContactState plus, minus;
        table.Blend(0, 1, t, directions, e + h * Eigen::Vector2d::Unit(axis), 1e-6, &plus);
        table.Blend(0, 1, t, directions, e - h * Eigen::Vector2d::Unit(axis), 1e-6, &minus);
        numeric.col(axis) = (plus.pressure_resultant - minus.pressure_resultant) / (2.0 * h);
        smooth = smooth && plus.resultant_jacobian.isApprox(minus.resultant_jacobian, 1e-12);
      }
      if (!smooth) continue;
      ++compared;
      EXPECT_LT((numeric - at.resultant_jacobian).norm(), 1e-5 * at.resultant_jacobian.norm())
          << limit << " " << e.transpose();
      EXPECT_NEAR(at.resultant_jacobian(0, 1), at.resultant_jacobian(1, 0), 0.0);
    }
  }
  EXPECT_GT(compared, 500);
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
