#include "surfaces/cylindrical/elastic/dense_cholesky.h"

#include <cstddef>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

namespace fitfeel::cylindrical {
namespace {

// A random SPD matrix B B^T / m + 1e-3 I: condition numbers of 1e3 to 1e4, as the compliance's
// submatrices.
Eigen::MatrixXd RandomSpd(Eigen::Index m, std::mt19937_64* rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd b(m, m);
  for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = normal(*rng);
  return b * b.transpose() / static_cast<double>(m) + 1e-3 * Eigen::MatrixXd::Identity(m, m);
}

TEST(DenseCholesky, SolvesAndFormsAsEigensLltDoesForEverySize) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  for (Eigen::Index m : {1, 2, 3, 7, 16, 33, 60, 120}) {
    const Eigen::MatrixXd a = RandomSpd(m, &rng);
    DenseCholesky chol;
    ASSERT_TRUE(chol.Compute(a));
    EXPECT_EQ(chol.size(), m);
    const Eigen::LLT<Eigen::MatrixXd> reference(a);
    Eigen::VectorXd x(m);
    for (Eigen::Index i = 0; i < m; ++i) x[i] = normal(rng);
    const Eigen::VectorXd expected = reference.solve(x);
    chol.SolveInPlace(x);
    EXPECT_LT((x - expected).norm(), 1e-9 * expected.norm()) << "m = " << m;
    EXPECT_LT((a * x - a * expected).norm(), 1e-9 * (a * expected).norm()) << "m = " << m;
    Eigen::MatrixX2d b(m, 2);
    for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = normal(rng);
    const Eigen::Matrix2d form = b.transpose() * reference.solve(b);
    EXPECT_LT((chol.InverseForm(b) - form).norm(), 1e-9 * form.norm()) << "m = " << m;
  }
}

// A factor kept through 300 random row removals and appends solves as a fresh factorization of
// the same principal submatrix does.
TEST(DenseCholesky, RowUpdatesSolveAsAFreshFactorization) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  const Eigen::Index n = 60;
  const Eigen::MatrixXd a = RandomSpd(n, &rng);
  std::vector<Eigen::Index> held, spare;
  for (Eigen::Index i = 0; i < n; ++i) (i % 3 == 0 ? spare : held).push_back(i);
  DenseCholesky chol;
  ASSERT_TRUE(chol.Compute(a(held, held)));
  for (int step = 0; step < 300; ++step) {
    const bool remove =
        !held.empty() && (spare.empty() || std::uniform_int_distribution<>(0, 1)(rng));
    if (remove) {
      const auto pos = std::uniform_int_distribution<std::size_t>(0, held.size() - 1)(rng);
      chol.Remove(static_cast<Eigen::Index>(pos));
      spare.push_back(held[pos]);
      held.erase(held.begin() + static_cast<std::ptrdiff_t>(pos));
    } else {
      const auto pos = std::uniform_int_distribution<std::size_t>(0, spare.size() - 1)(rng);
      const Eigen::Index c = spare[pos];
      Eigen::VectorXd column(static_cast<Eigen::Index>(held.size()));
      for (std::size_t r = 0; r < held.size(); ++r)
        column[static_cast<Eigen::Index>(r)] = a(held[r], c);
      ASSERT_TRUE(chol.Append(column, a(c, c)));
      held.push_back(c);
      spare.erase(spare.begin() + static_cast<std::ptrdiff_t>(pos));
    }
    ASSERT_EQ(chol.size(), static_cast<Eigen::Index>(held.size()));
    if (held.empty()) continue;
    const Eigen::MatrixXd sub = a(held, held);
    const Eigen::LLT<Eigen::MatrixXd> reference(sub);
    Eigen::VectorXd x(sub.rows());
    for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = normal(rng);
    const Eigen::VectorXd expected = reference.solve(x);
    chol.SolveInPlace(x);
    ASSERT_LT((x - expected).norm(), 1e-8 * expected.norm()) << "step " << step;
    Eigen::MatrixX2d b(sub.rows(), 2);
    for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = normal(rng);
    const Eigen::Matrix2d form = b.transpose() * reference.solve(b);
    ASSERT_LT((chol.InverseForm(b) - form).norm(), 1e-8 * form.norm()) << "step " << step;
  }
}

// The principal submatrix read in place is the factor of the submatrix copied out: the same
// numbers bit for bit (the section solver factors its contact sets so).
TEST(DenseCholesky, FactorsAPrincipalSubmatrixInPlace) {
  std::mt19937_64 rng(13);
  std::normal_distribution<double> normal;
  const Eigen::MatrixXd a = RandomSpd(90, &rng);
  for (const std::vector<int>& index :
       {std::vector<int>{0}, std::vector<int>{5, 2, 88, 40}, std::vector<int>{89, 0, 44, 1, 7}}) {
    std::vector<int> all = index;
    for (int i = 12; i < 80; i += 3) all.push_back(i);  // none of the listed ones
    DenseCholesky in_place, copied;
    ASSERT_TRUE(in_place.Compute(a, all));
    ASSERT_TRUE(copied.Compute(Eigen::MatrixXd(a(all, all))));
    ASSERT_EQ(in_place.size(), static_cast<Eigen::Index>(all.size()));
    Eigen::VectorXd x(in_place.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = normal(rng);
    Eigen::VectorXd y = x;
    in_place.SolveInPlace(x);
    copied.SolveInPlace(y);
    EXPECT_EQ(x, y);
    const Eigen::VectorXd b = a(all, all) * x;
    EXPECT_LT((Eigen::LLT<Eigen::MatrixXd>(a(all, all)).solve(b) - x).norm(), 1e-9 * x.norm());
  }
}

// Appending a column that makes the matrix singular is refused and leaves the factor as it was.
TEST(DenseCholesky, RefusesAnAppendThatLosesDefiniteness) {
  Eigen::Matrix2d a;
  a << 4, 2, 2, 3;
  DenseCholesky chol;
  ASSERT_TRUE(chol.Compute(a));
  EXPECT_FALSE(chol.Append(Eigen::Vector2d(4, 2), 4.0));  // a copy of the first column
  EXPECT_EQ(chol.size(), 2);
  Eigen::VectorXd x = Eigen::Vector2d(4, 2);
  chol.SolveInPlace(x);
  EXPECT_NEAR(x[0], 1.0, 1e-12);
  EXPECT_NEAR(x[1], 0.0, 1e-12);
}

TEST(DenseCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  DenseCholesky chol;
  Eigen::Matrix3d a;
  a << 4, 2, 0, 2, 1, 0, 0, 0, 1;  // singular: the second pivot is 0
  ASSERT_TRUE(chol.Compute(Eigen::Matrix2d::Identity()));
  EXPECT_FALSE(chol.Compute(a));
  EXPECT_EQ(chol.size(), 0);  // nothing half-factored to use
  a(1, 1) = 0.5;  // indefinite
  EXPECT_FALSE(chol.Compute(a));
  a(1, 1) = 2.0;
  EXPECT_TRUE(chol.Compute(a));
}

}  // namespace
}  // namespace fitfeel::cylindrical
