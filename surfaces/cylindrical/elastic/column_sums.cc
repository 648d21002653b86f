#include "surfaces/cylindrical/elastic/column_sums.h"

#include "framework/core/simd_clones.h"

namespace fitfeel::cylindrical {
namespace {

// Rows i .. i + B of ColumnSums: B accumulators held in registers over every column (each entry's
// sum still in the columns' order), instead of the whole output read and written per column.
template <int B>
inline void ColumnSumsRows(double* __restrict out, const double* __restrict a, Eigen::Index stride,
                           const double* __restrict x, Eigen::Index cols, bool skip_zero) {
  FITFEEL_NO_FP_CONTRACT
  double acc[B];
  for (int r = 0; r < B; ++r) acc[r] = 0.0;
  for (Eigen::Index j = 0; j < cols; ++j) {
    const double xj = x[j];
    if (skip_zero && xj == 0.0) continue;
    const double* __restrict column = a + j * stride;
    for (int r = 0; r < B; ++r) acc[r] = column[r] * xj + acc[r];
  }
  for (int r = 0; r < B; ++r) out[r] = acc[r];
}

FITFEEL_SIMD_CLONES void ColumnSumsLoop(double* __restrict out, const double* __restrict a,
                                        Eigen::Index stride, const double* __restrict x,
                                        Eigen::Index rows, Eigen::Index cols, bool skip_zero) {
  FITFEEL_NO_FP_CONTRACT
  Eigen::Index i = 0;
  for (; i + 16 <= rows; i += 16) ColumnSumsRows<16>(out + i, a + i, stride, x, cols, skip_zero);
  for (; i + 4 <= rows; i += 4) ColumnSumsRows<4>(out + i, a + i, stride, x, cols, skip_zero);
  for (; i < rows; ++i) ColumnSumsRows<1>(out + i, a + i, stride, x, cols, skip_zero);
}

}  // namespace

void ColumnSums(double* out, const double* a, Eigen::Index stride, const double* x,
                Eigen::Index rows, Eigen::Index cols, bool skip_zero) {
  ColumnSumsLoop(out, a, stride, x, rows, cols, skip_zero);
}

void TimesInOrder(const Eigen::MatrixXd& a, const double* x, double* out, bool skip_zero) {
  TimesInOrder(a, x, out, 0, a.rows(), skip_zero);
}

void TimesInOrder(const Eigen::MatrixXd& a, const double* x, double* out, Eigen::Index first,
                  Eigen::Index count, bool skip_zero) {
  // Eigen splits 128 columns or more into blocks whose sums it adds in turn, and takes a single
  // row as an inner product (its own order of the sum).
  if (a.cols() < 128 && (a.rows() > 1 || a.cols() == 1)) {
    ColumnSums(out + first, a.data() + first, a.outerStride(), x, count, a.cols(), skip_zero);
    return;
  }
  Eigen::Map<Eigen::VectorXd>(out, a.rows()).noalias() =
      a * Eigen::Map<const Eigen::VectorXd>(x, a.cols());
}

}  // namespace fitfeel::cylindrical
