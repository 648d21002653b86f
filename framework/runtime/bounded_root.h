#pragma once

#include <cmath>

namespace fitfeel {

// Result of a bounded root search (FindRootNear).
struct RootSearch {
  double solution = 0.0;  // the best point found (smallest |residual|)
  double residual = 0.0;  // its residual
  bool found = false;     // within tolerance, or a sign change bracketed it
  int evaluations = 0;
};

// How far FindRootNear looks: every fit's clearance and interference (ISO 286 limits of parts up
// to 500 mm stay below 1 mm) and every bore this framework models lie within it, m.
inline constexpr double kRootReach = 1.1e-3;
// The probe that measures the residual's local slope next to the start, m: far below every
// tolerance and texture height of a fit (um), far above the rounding of positions of a few mm.
inline constexpr double kRootProbe = 1e-9;

// Root of a nondecreasing residual r(s) near s = 0 (the previous tick's solution), for the 1 kHz
// tick: at most `budget` evaluations (>= 2), whatever r is, no allocation.
//
// r(0) within `tolerance`: done in one evaluation. Otherwise a probe kRootProbe towards the root
// gives the local slope and Newton's step from it lands on the root of a linear piece (the laws'
// radial forces are piecewise linear in the offset, or smooth on the scale of the texture, um), so
// a warm start usually needs 2-3 evaluations. Where the residual is flat (free motion), the search
// widens eightfold from 1 um up to kRootReach. Once a sign change brackets the root, each step is
// the secant through the last two points on the far side of the root, else on the near side (each
// exact on a linear piece), else a probe next to the far end for its slope, else bisection, always
// inside the bracket; it stops at the tolerance, at a bracket of 1 pm, or with the budget spent.
// The result is the best point evaluated (smallest |r|, the latest of equals); `found` says
// whether it met the tolerance or the root was bracketed.
template <class Residual>
RootSearch FindRootNear(Residual&& residual, double tolerance, int budget) noexcept {
  RootSearch out;
  auto eval = [&](double s) {
    ++out.evaluations;
    const double r = residual(s);
    if (out.evaluations == 1 || std::abs(r) <= std::abs(out.residual)) {
      out.solution = s;
      out.residual = r;
    }
    return r;
  };
  const double r0 = eval(0.0);
  if (std::abs(r0) <= tolerance) {
    out.found = true;
    return out;
  }
  if (!std::isfinite(r0)) return out;
  const double dir = r0 < 0.0 ? 1.0 : -1.0;  // the residual grows with s
  // The last two points on r0's side (near) and past the root (far, once bracketed).
  double near = 0.0, r_near = r0, near2 = 0.0, r_near2 = 0.0;
  double far = 0.0, r_far = 0.0, far2 = 0.0, r_far2 = 0.0;
  bool have_near2 = false, have_far2 = false, bracketed = false, probed_far = false;
  double reach = 1e-6;
  double s = dir * kRootProbe;
  auto inside = [&](double c) {
    return std::isfinite(c) && c > std::min(near, far) && c < std::max(near, far);
  };
  auto secant = [](double a, double ra, double b, double rb) {
    return ra != rb ? a - ra * (a - b) / (ra - rb) : std::nan("");
  };
  while (out.evaluations < budget) {
    const double r = eval(s);
    if (std::abs(r) <= tolerance) {
      out.found = true;
      return out;
    }
    if (!std::isfinite(r)) break;
    if ((r < 0.0) == (r0 < 0.0)) {
      near2 = near;
      r_near2 = r_near;
      have_near2 = true;
      near = s;
      r_near = r;
    } else {
      far2 = far;
      r_far2 = r_far;
      have_far2 = bracketed;
      far = s;
      r_far = r;
      bracketed = true;
    }
    if (!bracketed) {
      // Newton through the last two points on this side; widen eightfold where r is flat (or the
      // step would run backwards or out of reach).
      double next = secant(near, r_near, near2, r_near2);
      if (!std::isfinite(next) || (next - near) * dir <= 0.0 || std::abs(next) > kRootReach) {
        while (reach * 8.0 <= kRootReach && reach <= std::abs(near)) reach *= 8.0;
        if (reach <= std::abs(near)) return out;  // nothing within reach
        next = dir * reach;
      }
      s = next;
      continue;
    }
    if (std::abs(far - near) <= 1e-12) break;
    double next = have_far2 ? secant(far, r_far, far2, r_far2) : std::nan("");
    if (!inside(next) && have_near2) next = secant(near, r_near, near2, r_near2);
    if (!inside(next) && !probed_far && std::abs(far - near) > 2.0 * kRootProbe) {
      next = far - dir * kRootProbe;
      probed_far = true;
    }
    if (!inside(next)) next = 0.5 * (near + far);
    s = next;
  }
  out.found = bracketed;
  return out;
}

}  // namespace fitfeel
