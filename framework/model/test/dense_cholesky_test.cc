#include "framework/model/dense_cholesky.h"

#include <random>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

namespace fitfeel {
namespace {

// A random SPD matrix with a condition number of about 1e4, as the compliance's submatrices.
Eigen::MatrixXd RandomSpd(Eigen::Index m, std::mt19937_64* rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd q(m, m);
  for (Eigen::Index i = 0; i < q.size(); ++i) q.data()[i] = normal(*rng);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(q);
  const Eigen::MatrixXd basis = qr.householderQ();
  Eigen::VectorXd eig(m);
  for (Eigen::Index i = 0; i < m; ++i) eig[i] = std::pow(1e4, -static_cast<double>(i) / m);
  return basis * eig.asDiagonal() * basis.transpose();
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

TEST(DenseCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  DenseCholesky chol;
  Eigen::Matrix3d a;
  a << 4, 2, 0, 2, 1, 0, 0, 0, 1;  // singular: the second pivot is 0
  EXPECT_FALSE(chol.Compute(a));
  a(1, 1) = 0.5;  // indefinite
  EXPECT_FALSE(chol.Compute(a));
  a(1, 1) = 2.0;
  EXPECT_TRUE(chol.Compute(a));
}

}  // namespace
}  // namespace fitfeel
