#include "surfaces/cylindrical/fixed_lane_dot.h"

#include "framework/core/simd_clones.h"

namespace fitfeel::cylindrical {
namespace {

FITFEEL_SIMD_CLONES double LaneDot(const double* __restrict a, const double* __restrict b, int n) {
  FITFEEL_NO_FP_CONTRACT
  double lane[8] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  int k = 0;
  for (; k + 8 <= n; k += 8) {
    for (int q = 0; q < 8; ++q) lane[q] += a[k + q] * b[k + q];
  }
  double tail = 0.0;
  for (; k < n; ++k) tail += a[k] * b[k];
  return ((lane[0] + lane[1]) + (lane[2] + lane[3])) + ((lane[4] + lane[5]) + (lane[6] + lane[7])) +
         tail;
}

}  // namespace

double FixedLaneDot(const double* a, const double* b, int n) { return LaneDot(a, b, n); }

}  // namespace fitfeel::cylindrical
