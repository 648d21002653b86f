#include "surfaces/cylindrical/elastic/band_cholesky.h"

#include <cmath>

#include "framework/core/simd_clones.h"

namespace fitfeel::cylindrical {
namespace {

// The first column of row i and the last row of column k that may be nonzero in a band of
// half-bandwidth w (and, with `block`, in the blocks beside the diagonal's). Selects, not
// std::min / std::max: they are called from the clones below (framework/core/simd_clones.h).
std::ptrdiff_t FirstColumn(std::ptrdiff_t i, std::ptrdiff_t w, std::ptrdiff_t block) {
  std::ptrdiff_t first = i - w > 0 ? i - w : 0;
  if (block > 0) {
    const std::ptrdiff_t blocks = (i / block - 1) * block;
    first = blocks > first ? blocks : first;
  }
  return first;
}

std::ptrdiff_t LastRow(std::ptrdiff_t k, std::ptrdiff_t n, std::ptrdiff_t w,
                       std::ptrdiff_t block) {
  std::ptrdiff_t last = k + w < n - 1 ? k + w : n - 1;
  if (block > 0) {
    const std::ptrdiff_t blocks = (k / block + 2) * block - 1;
    last = blocks < last ? blocks : last;
  }
  return last;
}

FITFEEL_SIMD_CLONES bool FactorColumns(double* __restrict l, std::ptrdiff_t ld, std::ptrdiff_t n,
                                       std::ptrdiff_t w, std::ptrdiff_t block) {
  FITFEEL_NO_FP_CONTRACT
  for (std::ptrdiff_t j = 0; j < n; ++j) {
    double* __restrict column = l + j * ld;
    const std::ptrdiff_t last = LastRow(j, n, w, block);
    // Every column from the first that reaches row j: in a band each reaches fewer rows below
    // than the next, so a pass of four updates the rows all four reach, then the rows only the
    // later ones reach, each entry still taking its columns in order.
    std::ptrdiff_t k = FirstColumn(j, w, block);
    for (; k + 4 <= j; k += 4) {
      const double* __restrict d0 = l + k * ld;
      const double* __restrict d1 = d0 + ld;
      const double* __restrict d2 = d1 + ld;
      const double* __restrict d3 = d2 + ld;
      const double a0 = d0[j], a1 = d1[j], a2 = d2[j], a3 = d3[j];
      const std::ptrdiff_t r0 = LastRow(k, n, w, block), r1 = LastRow(k + 1, n, w, block),
                           r2 = LastRow(k + 2, n, w, block), r3 = LastRow(k + 3, n, w, block);
      const std::ptrdiff_t e0 = r0 < last ? r0 : last, e1 = r1 < last ? r1 : last,
                           e2 = r2 < last ? r2 : last, e3 = r3 < last ? r3 : last;
      for (std::ptrdiff_t i = j; i <= e0; ++i) {
        column[i] = column[i] - a0 * d0[i] - a1 * d1[i] - a2 * d2[i] - a3 * d3[i];
      }
      for (std::ptrdiff_t i = e0 + 1; i <= e1; ++i) {
        column[i] = column[i] - a1 * d1[i] - a2 * d2[i] - a3 * d3[i];
      }
      for (std::ptrdiff_t i = e1 + 1; i <= e2; ++i) column[i] = column[i] - a2 * d2[i] - a3 * d3[i];
      for (std::ptrdiff_t i = e2 + 1; i <= e3; ++i) column[i] -= a3 * d3[i];
    }
    for (; k < j; ++k) {
      const double* __restrict done = l + k * ld;
      const double ljk = done[j];
      const std::ptrdiff_t reach = LastRow(k, n, w, block);
      const std::ptrdiff_t end = reach < last ? reach : last;
      for (std::ptrdiff_t i = j; i <= end; ++i) column[i] -= ljk * done[i];
    }
    if (!(column[j] > 0.0)) return false;
    const double pivot = std::sqrt(column[j]);
    column[j] = pivot;
    for (std::ptrdiff_t i = j + 1; i <= last; ++i) column[i] /= pivot;
  }
  return true;
}

// y[0, n) -= sum over t < terms of c[t] x_t[0, n), x_t = x + t * stride, subtracted in the order
// of t: a band solve's step for one row over every right-hand side at once, in one call (a call
// per term was a third of the elements' cost on the shipped parts).
FITFEEL_SIMD_CLONES void SubtractCombination(double* __restrict y, const double* __restrict x,
                                             std::ptrdiff_t stride, const double* __restrict c,
                                             int terms, int n) {
  FITFEEL_NO_FP_CONTRACT
  for (int t = 0; t < terms; ++t) {
    const double* __restrict xt = x + t * stride;
    const double a = c[t];
    for (int j = 0; j < n; ++j) y[j] -= a * xt[j];
  }
}

}  // namespace

bool FactorBand(double* l, std::ptrdiff_t ld, std::ptrdiff_t n, std::ptrdiff_t w,
                std::ptrdiff_t block) {
  return FactorColumns(l, ld, n, w, block);
}

BandCholesky::BandCholesky(int n, int w, int block)
    : n_(n), w_(w), block_(block), band_(static_cast<std::size_t>(n) * (w + 1), 0.0) {}

int BandCholesky::FirstInRow(int i) const {
  return static_cast<int>(FirstColumn(i, w_, block_));
}

int BandCholesky::LastInColumn(int k) const {
  return static_cast<int>(LastRow(k, n_, w_, block_));
}

bool BandCholesky::Factor() { return FactorBand(band_.data(), w_, n_, w_, block_); }

void BandCholesky::Solve(double* x, int cols, const std::vector<int>& first) const {
  Forward(x, cols, first);
  // Backwards, row i takes column i of L below the diagonal (contiguous in the band).
  for (int i = n_ - 1; i >= 0; --i) {
    double* xi = x + static_cast<std::size_t>(i) * cols;
    SubtractCombination(xi, xi + cols, cols, band_.data() + Index(i, i) + 1, LastInColumn(i) - i,
                        cols);
    const double d = at(i, i);
    for (int j = 0; j < cols; ++j) xi[j] /= d;
  }
}

void BandCholesky::Forward(double* x, int cols, const std::vector<int>& first) const {
  std::vector<double> row(static_cast<std::size_t>(w_));
  int live = 0;  // columns with first <= i
  for (int i = 0; i < n_; ++i) {
    while (live < cols && first[static_cast<std::size_t>(live)] <= i) ++live;
    double* xi = x + static_cast<std::size_t>(i) * cols;
    // Row i of L holds columns lo .. i - 1 (strided in the band: gathered); the rows of X they
    // take are adjacent.
    const int lo = FirstInRow(i);
    for (int t = 0; t < i - lo; ++t) row[static_cast<std::size_t>(t)] = at(i, lo + t);
    SubtractCombination(xi, x + static_cast<std::size_t>(lo) * cols, cols, row.data(), i - lo,
                        live);
    const double d = at(i, i);
    for (int j = 0; j < live; ++j) xi[j] /= d;
  }
}

}  // namespace fitfeel::cylindrical
