#pragma once

#include <span>

#include <Eigen/Core>

namespace fitfeel::cylindrical {

// Cholesky factor L (A = L L^T) of a small dense symmetric positive definite matrix, as the
// section contact's pivoting steps need it: tens of thousands of principal submatrices of 10 to
// 120 rows in one prepare, each used for one or two solves and for the 2x2 form B^T A^-1 B of the
// contact stiffness, and most differing from the one before by a few rows and columns. So the
// factor is updated by rows (Append, Remove: O(m^2) each instead of O(m^3 / 3) for a new
// factorization), a new factorization reads the principal submatrix in place, and the form is a
// forward substitution over contiguous columns (Eigen's LLT and its triangular solve for two
// right-hand sides spend much of these sizes on blocking and copies, measured in a prepare). A new
// factorization is band_cholesky.h's FactorBand over the whole band. Prepare-time only.
class DenseCholesky {
 public:
  // Factors `a` (only its lower triangle is read). False when a pivot is not positive: the
  // matrix is not positive definite (to rounding), and the factor is left empty.
  bool Compute(const Eigen::MatrixXd& a);
  // The same for the principal submatrix a(index, index), read in place.
  bool Compute(const Eigen::MatrixXd& a, std::span<const int> index);
  // Extends A by one row and column at the end: `column` = the new column's entries in the rows of
  // A (size() values), `diagonal` its own. False (and the factor unchanged) when the extended
  // matrix is not safely positive definite: the caller factors it anew.
  bool Append(const Eigen::Ref<const Eigen::VectorXd>& column, double diagonal);
  // Removes row and column `position` of A (a rank-one update of the trailing factor).
  void Remove(Eigen::Index position);

  Eigen::Index size() const { return size_; }
  // x <- A^-1 x.
  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> x) const;
  // B^T A^-1 B for a B of two columns (= X^T X with X = L^-1 B).
  Eigen::Matrix2d InverseForm(Eigen::MatrixX2d b) const;
  // The same for any number of columns.
  Eigen::MatrixXd InverseFormOf(Eigen::MatrixXd b) const;

 private:
  // Fills the lower triangle from entry(i, j) (i >= j) and factors it.
  template <typename Entry>
  bool Factor(Eigen::Index m, const Entry& entry);
  // L in the top-left size_ x size_ lower triangle; the storage may be larger (room to append).
  Eigen::MatrixXd l_;
  Eigen::Index size_ = 0;
};

}  // namespace fitfeel::cylindrical
