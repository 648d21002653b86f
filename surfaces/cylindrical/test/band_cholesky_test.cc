#include "surfaces/cylindrical/elastic/band_cholesky.h"

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include "surfaces/cylindrical/elastic/dense_cholesky.h"

namespace fitfeel::cylindrical {
namespace {

// A random symmetric positive definite matrix of half-bandwidth w (diagonally dominant), zero
// outside the band and, with `block`, outside the blocks beside the diagonal's.
Eigen::MatrixXd RandomBand(int n, int w, int block, std::mt19937_64* rng) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = std::max(0, i - w); j < i; ++j) {
      if (block > 0 && j < (i / block - 1) * block) continue;
      a(i, j) = a(j, i) = entry(*rng);
    }
  }
  for (int i = 0; i < n; ++i) a(i, i) = 2.0 * w + 1.0 + entry(*rng);
  return a;
}

BandCholesky Filled(const Eigen::MatrixXd& a, int w, int block) {
  BandCholesky band(static_cast<int>(a.rows()), w, block);
  for (int i = 0; i < a.rows(); ++i) {
    for (int j = std::max(0, i - w); j <= i; ++j) band.at(i, j) = a(i, j);
  }
  return band;
}

// The band's factor is the dense factor's, entry for entry: one factorization, which skips only
// the band's (and the blocks') zeros.
TEST(BandCholesky, FactorsAsTheWholeBandDoesBitForBit) {
  std::mt19937_64 rng(3);
  for (const auto& [n, w, block] : std::vector<std::array<int, 3>>{
           {1, 0, 0}, {9, 0, 0}, {12, 3, 0}, {40, 7, 0}, {40, 39, 0}, {36, 5, 3}, {48, 7, 4}}) {
    const Eigen::MatrixXd a = RandomBand(n, w, block, &rng);
    BandCholesky band = Filled(a, w, block);
    ASSERT_TRUE(band.Factor());
    Eigen::MatrixXd dense = a;
    ASSERT_TRUE(FactorBand(dense.data(), n, n, n - 1, 0));
    for (int i = 0; i < n; ++i) {
      for (int j = std::max(0, i - w); j <= i; ++j) {
        EXPECT_EQ(band.at(i, j), dense(i, j)) << n << " " << w << " " << block;
      }
    }
  }
}

// Solve and Forward against Eigen's LLT, for many right-hand sides, some zero above a first row.
TEST(BandCholesky, SolvesManyRightHandSidesAsEigensLltDoes) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  const int n = 60, w = 9, cols = 5;
  const Eigen::MatrixXd a = RandomBand(n, w, 0, &rng);
  BandCholesky band = Filled(a, w, 0);
  ASSERT_TRUE(band.Factor());
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  RowMajor x = RowMajor::Zero(n, cols);
  const std::vector<int> first{0, 0, 10, 30, 59};
  for (int c = 0; c < cols; ++c) {
    for (int i = first[static_cast<std::size_t>(c)]; i < n; ++i) x(i, c) = normal(rng);
  }
  const Eigen::LLT<Eigen::MatrixXd> reference(a);
  const Eigen::MatrixXd expected = reference.solve(Eigen::MatrixXd(x));
  const Eigen::MatrixXd forward = reference.matrixL().solve(Eigen::MatrixXd(x));
  RowMajor y = x;
  band.Forward(y.data(), cols, first);
  EXPECT_LT((Eigen::MatrixXd(y) - forward).norm(), 1e-12 * forward.norm());
  band.Solve(x.data(), cols, first);
  EXPECT_LT((Eigen::MatrixXd(x) - expected).norm(), 1e-12 * expected.norm());
}

TEST(BandCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  BandCholesky band(3, 1);
  band.at(0, 0) = 1.0;
  band.at(1, 0) = 2.0;
  band.at(1, 1) = 1.0;
  band.at(2, 1) = 0.0;
  band.at(2, 2) = 1.0;
  EXPECT_FALSE(band.Factor());
}

}  // namespace
}  // namespace fitfeel::cylindrical
