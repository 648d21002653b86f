#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "framework/core/export.h"

namespace fitfeel {

// Cholesky factor L (A = L L^T) of a small dense symmetric positive definite matrix, as the
// section contact's pivoting steps need it: tens of thousands of principal submatrices of 10 to
// 120 rows in one prepare, each used for one or two solves and for the 2x2 form B^T A^-1 B of the
// contact stiffness. Eigen's LLT factors; the form is a forward substitution over contiguous
// columns of L (Eigen's triangular solve for two right-hand sides spends about four times as long
// on blocking at these sizes, measured in a prepare). Prepare-time only.
class FITFEEL_API DenseCholesky {
 public:
  // Factors `a` (only its lower triangle is read). False when a pivot is not positive: the
  // matrix is not positive definite (to rounding), and the factor must not be used.
  bool Compute(const Eigen::MatrixXd& a);

  Eigen::Index size() const { return llt_.rows(); }
  // x <- A^-1 x.
  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> x) const;
  // B^T A^-1 B for a B of two columns (= X^T X with X = L^-1 B).
  Eigen::Matrix2d InverseForm(Eigen::MatrixX2d b) const;

 private:
  Eigen::LLT<Eigen::MatrixXd> llt_;
};

}  // namespace fitfeel
