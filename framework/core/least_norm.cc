#include "framework/core/least_norm.h"

#include <Eigen/QR>

namespace fitfeel {

Eigen::VectorXd LeastNormSolve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  return a.completeOrthogonalDecomposition().solve(b);
}

Eigen::MatrixXd LeastNormSolveColumns(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.completeOrthogonalDecomposition().solve(b);
}

}  // namespace fitfeel
