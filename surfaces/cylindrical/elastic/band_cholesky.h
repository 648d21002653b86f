#pragma once

#include <cstddef>
#include <vector>

namespace fitfeel::cylindrical {

// The elastic solver's one Cholesky factorization, A = L L^T for a symmetric positive definite
// matrix held as the lower band of half-bandwidth w, column-major: entry (i, j), j <= i <= j + w,
// at l[j * ld + i], so that each column's entries are contiguous. `block` > 0: the matrix is also
// block tridiagonal in blocks of that size (w = 2 block - 1), so row i is zero left of the block
// before its own, and so is L (a factor keeps each row's first nonzero); the factor skips those
// zeros. A dense matrix is the whole band (w = n - 1, ld >= n, block 0): DenseCholesky factors
// the section contact's matrices so, BandCholesky the axial coupling's element stiffness.
//
// Left-looking: column j takes the columns before it that reach its row (four per pass over it,
// each a contiguous update that vectorises), then its pivot's square root and a division by it.
// Each entry subtracts its products in column order, without contraction, so every instruction
// set gives the same factor (framework/core/simd_clones.h). False when a pivot is not positive:
// the matrix is not positive definite (to rounding). Prepare-time only.
bool FactorBand(double* l, std::ptrdiff_t ld, std::ptrdiff_t n, std::ptrdiff_t w,
                std::ptrdiff_t block);

// A band matrix of n rows and half-bandwidth w with its own storage (n (w + 1) values, zeroed
// here), to be filled through at(), factored in place and solved for many right-hand sides at
// once: the axial coupling's element stiffness (its numbering, radial index fastest, keeps the
// band two radial stations wide, and a band factor has no fill outside it: n w^2 / 2 operations,
// no reordering).
class BandCholesky {
 public:
  BandCholesky(int n, int w, int block = 0);

  // Row i, column j <= i, j >= i - w.
  double& at(int i, int j) { return band_[Index(i, j)]; }
  double at(int i, int j) const { return band_[Index(i, j)]; }
  // Factors in place (FactorBand); false if a pivot is not positive.
  bool Factor();
  // X <- L^-T L^-1 X = A^-1 X for the columns of a row-major X (n rows, `cols` columns): row
  // operations, which run over every right-hand side at once (contiguous, vectorised) instead of
  // one band solve each. Column j is zero above row first[j] (nondecreasing in j): the forward
  // pass skips the columns that are still zero.
  void Solve(double* x, int cols, const std::vector<int>& first) const;
  // X <- L^-1 X, the forward half of Solve: for a' A^-1 b = (L^-1 a)' (L^-1 b).
  void Forward(double* x, int cols, const std::vector<int>& first) const;

 private:
  std::size_t Index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(w_) +
           static_cast<std::size_t>(i);
  }
  // The profile, both ways: the first column of row i and the last row of column k that may be
  // nonzero (the band's edge, or with `block` the edge of the blocks beside the diagonal's).
  int FirstInRow(int i) const;
  int LastInColumn(int k) const;

  int n_, w_, block_;
  std::vector<double> band_;
};

}  // namespace fitfeel::cylindrical
