#include "framework/model/dense_cholesky.h"

namespace fitfeel {

bool DenseCholesky::Compute(const Eigen::MatrixXd& a) {
  llt_.compute(a);
  return llt_.info() == Eigen::Success;
}

void DenseCholesky::SolveInPlace(Eigen::Ref<Eigen::VectorXd> x) const { llt_.solveInPlace(x); }

Eigen::Matrix2d DenseCholesky::InverseForm(Eigen::MatrixX2d b) const {
  const Eigen::MatrixXd& l = llt_.matrixLLT();  // L in the lower triangle
  const Eigen::Index m = l.rows();
  for (Eigen::Index j = 0; j < m; ++j) {
    b.row(j) /= l(j, j);
    const Eigen::Index below = m - j - 1;
    b.col(0).tail(below) -= b(j, 0) * l.col(j).tail(below);
    b.col(1).tail(below) -= b(j, 1) * l.col(j).tail(below);
  }
  return b.transpose() * b;
}

}  // namespace fitfeel
