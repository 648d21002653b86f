#include "surfaces/cylindrical/elastic/column_sums.h"

#include "framework/core/simd_clones.h"

namespace fitfeel::cylindrical {
namespace {

FITFEEL_SIMD_CLONES void ColumnSumsLoop(double* __restrict out, const double* __restrict a,
                                        Eigen::Index stride, const double* __restrict x,
                                        Eigen::Index rows, Eigen::Index cols, bool skip_zero) {
  FITFEEL_NO_FP_CONTRACT
  for (Eigen::Index i = 0; i < rows; ++i) out[i] = 0.0;
  for (Eigen::Index j = 0; j < cols; ++j) {
    const double xj = x[j];
    if (skip_zero && xj == 0.0) continue;
    const double* __restrict column = a + j * stride;
    for (Eigen::Index i = 0; i < rows; ++i) out[i] = column[i] * xj + out[i];
  }
}

}  // namespace

void ColumnSums(double* out, const double* a, Eigen::Index stride, const double* x,
                Eigen::Index rows, Eigen::Index cols, bool skip_zero) {
  ColumnSumsLoop(out, a, stride, x, rows, cols, skip_zero);
}

void TimesInOrder(const Eigen::MatrixXd& a, const double* x, double* out, bool skip_zero) {
  // Eigen splits 128 columns or more into blocks whose sums it adds in turn, and takes a single
  // row as an inner product (its own order of the sum).
  if (a.cols() < 128 && (a.rows() > 1 || a.cols() == 1)) {
    ColumnSums(out, a.data(), a.outerStride(), x, a.rows(), a.cols(), skip_zero);
    return;
  }
  Eigen::Map<Eigen::VectorXd>(out, a.rows()).noalias() =
      a * Eigen::Map<const Eigen::VectorXd>(x, a.cols());
}

}  // namespace fitfeel::cylindrical
