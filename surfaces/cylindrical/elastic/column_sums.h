#pragma once

#include <Eigen/Core>

namespace fitfeel::cylindrical {

// out = a x (a column-major, rows x cols, leading dimension `stride`), each entry summed over the
// columns in their order from +0: the sums Eigen's matrix-vector product forms for a matrix of
// fewer than 128 columns and more than one row (Eigen/src/Core/products/GeneralMatrixVector.h:
// one block of every column, its accumulator from zero, added to the zeroed destination). A
// product `out = a * x` of such a matrix written with it keeps its bits, without Eigen's call,
// its temporaries and its per-row-packet bookkeeping (most of a 13 x 13 product's cost). Compiled
// also for AVX2 and AVX-512 (framework/core/simd_clones.h); no product and sum are fused.
// `skip_zero`: columns whose x is zero are left out, which changes no sum (a zero product added to
// a sum that started at +0 leaves it as it is: it is never -0) where a is finite.
void ColumnSums(double* out, const double* a, Eigen::Index stride, const double* x,
                Eigen::Index rows, Eigen::Index cols, bool skip_zero);

// out = a * x (`out`, rows values, may not overlap x): ColumnSums where Eigen forms those sums,
// else Eigen's own product.
void TimesInOrder(const Eigen::MatrixXd& a, const double* x, double* out, bool skip_zero = false);
// The same for the rows first .. first + count - 1 of the product alone (out[first ..]; the other
// entries of `out` untouched where ColumnSums forms them, written where Eigen does): each entry's
// sum is the whole product's.
void TimesInOrder(const Eigen::MatrixXd& a, const double* x, double* out, Eigen::Index first,
                  Eigen::Index count, bool skip_zero);

}  // namespace fitfeel::cylindrical
