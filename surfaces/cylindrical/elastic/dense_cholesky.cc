#include "surfaces/cylindrical/elastic/dense_cholesky.h"

#include <algorithm>
#include <cmath>

#include "framework/core/simd_clones.h"
#include "surfaces/cylindrical/elastic/band_cholesky.h"
#include "surfaces/cylindrical/fixed_lane_dot.h"

namespace fitfeel::cylindrical {
namespace {

// b0, b1 <- L^-1 b0, L^-1 b1 for the leading m x m block of the lower-triangular, column-major l
// (leading dimension ld): the section solver's most frequent product, compiled also for AVX2 and
// AVX-512 (framework/core/simd_clones.h).
FITFEEL_SIMD_CLONES void ForwardSubstituteTwo(const double* __restrict l, Eigen::Index ld,
                                              Eigen::Index m, double* __restrict b0,
                                              double* __restrict b1) {
  FITFEEL_NO_FP_CONTRACT
  for (Eigen::Index j = 0; j < m; ++j) {
    const double* __restrict column = l + j * ld;
    const double x0 = b0[j] / column[j];
    const double x1 = b1[j] / column[j];
    b0[j] = x0;
    b1[j] = x1;
    for (Eigen::Index i = j + 1; i < m; ++i) {
      b0[i] -= x0 * column[i];
      b1[i] -= x1 * column[i];
    }
  }
}

// x <- (L L^T)^-1 x for the same block of l: L y = x column by column, then L^T x = y row by row
// of L^T (a column of L, contiguous), each row's sum a FixedLaneDot, which adds the same numbers
// in the same order on every instruction set.
FITFEEL_SIMD_CLONES void SolveLowerThenTransposed(const double* __restrict l, Eigen::Index ld,
                                                  Eigen::Index m, double* __restrict x) {
  FITFEEL_NO_FP_CONTRACT
  for (Eigen::Index j = 0; j < m; ++j) {
    const double* __restrict column = l + j * ld;
    const double y = x[j] / column[j];
    x[j] = y;
    for (Eigen::Index i = j + 1; i < m; ++i) x[i] -= y * column[i];
  }
  for (Eigen::Index j = m - 1; j >= 0; --j) {
    const double* __restrict column = l + j * ld;
    const double sum = FixedLaneDot(column + j + 1, x + j + 1, static_cast<int>(m - j - 1));
    x[j] = (x[j] - sum) / column[j];
  }
}

}  // namespace

bool DenseCholesky::Compute(const Eigen::MatrixXd& a) {
  return Factor(a.rows(), [&](Eigen::Index i, Eigen::Index j) { return a(i, j); });
}

bool DenseCholesky::Compute(const Eigen::MatrixXd& a, std::span<const int> index) {
  return Factor(static_cast<Eigen::Index>(index.size()), [&](Eigen::Index i, Eigen::Index j) {
    return a(index[static_cast<std::size_t>(i)], index[static_cast<std::size_t>(j)]);
  });
}

template <typename Entry>
bool DenseCholesky::Factor(Eigen::Index m, const Entry& entry) {
  if (l_.rows() < m) l_.resize(m, m);
  const Eigen::Index ld = l_.rows();
  for (Eigen::Index j = 0; j < m; ++j) {
    for (Eigen::Index i = j; i < m; ++i) l_(i, j) = entry(i, j);
  }
  const bool ok = FactorBand(l_.data(), ld, m, m - 1, 0);  // the whole band
  size_ = ok ? m : 0;  // a failed factor holds nothing usable
  return ok;
}

bool DenseCholesky::Append(const Eigen::Ref<const Eigen::VectorXd>& column, double diagonal) {
  const Eigen::Index s = size_;
  // The new row r of L solves L r = column; its diagonal is what is left of A's.
  Eigen::VectorXd r = column;
  const auto l = l_.topLeftCorner(s, s);
  for (Eigen::Index j = 0; j < s; ++j) {
    r[j] /= l(j, j);
    r.tail(s - j - 1) -= r[j] * l.col(j).tail(s - j - 1);
  }
  const double rest = diagonal - r.squaredNorm();
  // A pivot of less than 1e-8 of the diagonal has lost most of its digits to cancellation.
  if (!(rest > 1e-8 * diagonal)) return false;
  if (l_.rows() <= s)
    l_.conservativeResize(std::max<Eigen::Index>(2 * s, 8), std::max<Eigen::Index>(2 * s, 8));
  l_.row(s).head(s) = r.transpose();
  l_(s, s) = std::sqrt(rest);
  size_ = s + 1;
  return true;
}

void DenseCholesky::Remove(Eigen::Index position) {
  const Eigen::Index s = size_;
  const Eigen::Index p = position;
  // Rows below p lose their entry x in column p: the trailing factor T must become T' with
  // T' T'^T = T T^T + x x^T, a rank-one update by Givens-like steps down T's columns.
  Eigen::VectorXd x = l_.col(p).segment(p + 1, s - p - 1);
  for (Eigen::Index k = p + 1; k < s; ++k) {
    const Eigen::Index i = k - p - 1;  // x's index of row k
    const double lkk = l_(k, k);
    const double r = std::hypot(lkk, x[i]);
    const double c = r / lkk, sn = x[i] / lkk;
    l_(k, k) = r;
    const Eigen::Index below = s - k - 1;
    auto lower = l_.col(k).segment(k + 1, below);
    auto rest = x.segment(i + 1, below);
    lower = (lower + sn * rest) / c;
    rest = c * rest - sn * lower;
  }
  // Close the gap: columns after p move left and rows after p move up by one.
  for (Eigen::Index j = 0; j < s - 1; ++j) {
    const Eigen::Index from_col = j < p ? j : j + 1;
    for (Eigen::Index i = std::max(j, p); i < s - 1; ++i) l_(i, j) = l_(i + 1, from_col);
  }
  size_ = s - 1;
}

void DenseCholesky::SolveInPlace(Eigen::Ref<Eigen::VectorXd> x) const {
  SolveLowerThenTransposed(l_.data(), l_.rows(), size_, x.data());
}

Eigen::Matrix2d DenseCholesky::InverseForm(Eigen::MatrixX2d b) const {
  ForwardSubstituteTwo(l_.data(), l_.rows(), size_, b.col(0).data(), b.col(1).data());
  return b.transpose() * b;
}

Eigen::MatrixXd DenseCholesky::InverseFormOf(Eigen::MatrixXd b) const {
  l_.topLeftCorner(size_, size_).triangularView<Eigen::Lower>().solveInPlace(b);
  return b.transpose() * b;
}

}  // namespace fitfeel::cylindrical
