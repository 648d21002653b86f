#include "framework/core/root_finding.h"

#include <Eigen/Eigenvalues>

namespace fitfeel {

bool StiffNewtonTerms(const Eigen::Matrix2d& k, const Eigen::Vector2d& residual,
                      Eigen::Vector2d term[2], Eigen::Vector2d* free) noexcept {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(0.5 * (k + k.transpose()));
  const double largest = eig.eigenvalues().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest)) return false;
  free->setZero();
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector2d v = eig.eigenvectors().col(i);
    const double lambda = eig.eigenvalues()[i];
    term[i].setZero();
    if (lambda > 1e-6 * largest) {
      term[i] = (v.dot(residual) / lambda) * v;
    } else {
      *free = v;
    }
  }
  return true;
}

}  // namespace fitfeel
