#pragma once

// Root finders of the per-tick searches (the constrained stage's settle and god object): they
// allocate nothing and take a bounded number of evaluations.

#include <cmath>

#include <Eigen/Core>

#include "framework/core/export.h"

namespace fitfeel {

// Illinois false position on a bracket [lo, hi] whose residuals f_lo and f_hi have opposite
// signs: superlinear on the piecewise-linear laws, never leaves the bracket; stops at 1 pm of
// position, at |f| <= tolerance or after `steps` evaluations (the tick's bound). Returns hi if
// no step is taken.
template <typename Residual>
double IllinoisRoot(const Residual& f, double lo, double hi, double f_lo, double f_hi,
                    double tolerance, int steps) noexcept {
  double x = hi;
  int side = 0;
  for (int k = 0; k < steps && std::abs(hi - lo) > 1e-12; ++k) {
    x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    const double r = f(x);
    if (std::abs(r) <= tolerance) break;
    if ((r < 0.0) == (f_hi < 0.0)) {
      hi = x;
      f_hi = r;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    } else {
      lo = x;
      f_lo = r;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    }
  }
  return x;
}

// A 2x2 contact stiffness that holds the part in both directions, well enough conditioned to step
// on without measuring it anew (det > 1e-2 trace^2: the softer direction at least ~1 % of the
// stiffer).
inline bool HoldsBothWays(const Eigen::Matrix2d& k) noexcept {
  const double det = k.determinant(), trace = k.trace();
  return trace > 0.0 && det > 1e-2 * trace * trace;
}

// The Newton step of a 2x2 contact stiffness k (-dF/d(offset), symmetrised) against the
// unbalanced force `residual`, one term per eigen-direction that has stiffness (an eigenvalue
// above 1e-6 of the largest; zero for a direction without, which `free` receives, zero if none).
// False, with nothing written, when nothing holds the part (no positive finite eigenvalue).
FITFEEL_API bool StiffNewtonTerms(const Eigen::Matrix2d& k, const Eigen::Vector2d& residual,
                                  Eigen::Vector2d term[2], Eigen::Vector2d* free) noexcept;

}  // namespace fitfeel
