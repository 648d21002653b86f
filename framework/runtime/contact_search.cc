#include "framework/runtime/contact_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/root_finding.h"

namespace fitfeel {

void SetGap(StageOutput* out) noexcept {
  out->gap = std::numeric_limits<double>::infinity();
  out->gap_direction.setZero();
  const ContactState& c = out->contact;
  // In clearance, S_A(gamma) - delta d is the free way outwards along the offset: where a part
  // resting against the bore (offset towards the wall it rests on) would fall to.
  if (out->stiffness == 0.0 && c.engaged && !c.interference && c.offset_distance > 0.0 &&
      c.assembly_extent >= c.offset_distance) {
    out->gap = c.assembly_extent - c.offset_distance;
    out->gap_direction = out->pose.offset / out->pose.offset.norm();
  }
}

Eigen::Vector2d ContactSearch::ProbeAt(const Eigen::Vector2d& offset, const MatingMotion& motion,
                                       StageOutput* work) const noexcept {
  work->pose.offset = offset;
  analyzer_.Evaluate(work->pose, &work->contact);
  ++work->contact_evaluations;
  work->wrench.SetZero();
  law_.Evaluate(work->contact, motion, &work->wrench);
  return {work->wrench.force.x(), work->wrench.force.z()};
}

Eigen::Vector2d ContactSearch::ForceAt(const Eigen::Vector2d& offset, const MatingMotion& motion,
                                       StageOutput* work) const noexcept {
  if (work->pose.offset == offset) return {work->wrench.force.x(), work->wrench.force.z()};
  return ProbeAt(offset, motion, work);
}

bool ContactSearch::SolveAlong(const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                               double target, double tolerance, const MatingMotion& motion,
                               StageOutput* work, double* solution, double spring, double* slope,
                               const double* hint) const noexcept {
  // Support the contact gives along -axis with the part at origin + s * axis, minus the target:
  // negative while the part would move further along the axis. The laws' radial force grows
  // monotonically with the offset into a wall (eq. 9's spring, eqs. 10-12's interference), so
  // the root is unique up to a flat stretch of free motion, where any point is an equilibrium.
  // The last two evaluations (both at s = 0 until a second one is made).
  double last_s[2] = {0.0, 0.0}, last_r[2] = {0.0, 0.0};
  auto residual = [&](double s) {
    const double r = -ForceAt(origin + s * axis, motion, work).dot(axis) - (target - spring * s);
    last_s[0] = last_s[1];
    last_r[0] = last_r[1];
    last_s[1] = s;
    last_r[1] = r;
    return r;
  };
  // The secant of the last two evaluations, where it is a slope the next search can start from.
  auto learn = [&] {
    if (slope == nullptr || last_s[1] == last_s[0]) return;
    const double secant = (last_r[1] - last_r[0]) / (last_s[1] - last_s[0]);
    if (secant > 0.0 && std::isfinite(secant)) *slope = secant;
  };
  // Probes s; true (the solution taken, the slope learnt) where its residual is within the
  // tolerance.
  auto lands = [&](double s, double* r) {
    *r = residual(s);
    if (std::abs(*r) > tolerance) return false;
    *solution = s;
    learn();
    return true;
  };
  // The root is usually within a few um of the origin (the previous tick's equilibrium): check
  // the origin first, then (with a slope from the last search) take a Newton step, exact on a
  // linear spring; then bracket on the side the residual points to, starting 1 um away (or eight
  // Newton steps) and widening eightfold up to 1 mm: beyond every fit's clearance and
  // interference (ISO 286 limits of parts up to 500 mm stay below 1 mm) and within every bore
  // this framework models.
  // Where the last probe was (a settle's next search from its last root), its numbers stand.
  const double r0 = residual(0.0);
  if (std::abs(r0) <= tolerance) {
    *solution = 0.0;
    return true;
  }
  double lo = 0.0, hi = 0.0, r_lo = r0, r_hi = r0;
  bool bracketed = false;
  double reach = 1e-6;
  // The bracket between two probes whose residuals lie either side of zero.
  auto bracket = [&](double a, double r_a, double b, double r_b) {
    bracketed = true;
    lo = std::min(a, b);
    hi = std::max(a, b);
    r_lo = lo == a ? r_a : r_b;
    r_hi = hi == a ? r_a : r_b;
  };
  // Around the last root: from 10 nm, widening eightfold, on the side its residual points to
  // (the residual rises with s), at most to the origin, whose residual is known.
  if (hint != nullptr && std::isfinite(*hint) && *hint != 0.0 && std::abs(*hint) <= 1.1e-3) {
    const double s1 = *hint;
    const double r1 = residual(s1);
    if (std::abs(r1) <= tolerance) {
      *solution = s1;
      return true;
    }
    const double toward = r1 > 0.0 ? -1.0 : 1.0;  // where the root lies from s1
    double a = s1, r_a = r1;
    // With a slope from the last root the first step is Newton's (the root moves with the device,
    // a fraction of a micrometre per tick), and the widening continues from there.
    double base = s1;
    if (slope != nullptr && *slope > 0.0) {
      const double newton = -r1 / *slope;
      if (std::isfinite(newton) && std::abs(newton) <= 1e-4) base = s1 + 1.01 * newton;
    }
    for (double step = base == s1 ? 1e-8 : 0.0; step <= 1.1e-3 && !bracketed;
         step = step == 0.0 ? 1e-8 : 8.0 * step) {
      double b = base + toward * step;
      const bool past_origin = (b - 0.0) * (s1 - 0.0) <= 0.0;
      const double r_b = past_origin ? r0 : residual(b);
      if (past_origin) b = 0.0;
      if ((r_b > 0.0) != (r1 > 0.0)) {
        bracket(a, r_a, b, r_b);
      } else if (past_origin) {
        break;
      }
      a = b;
      r_a = r_b;
    }
  }
  if (!bracketed && slope != nullptr && *slope > 0.0) {
    const double s1 = -r0 / *slope;
    if (std::isfinite(s1) && s1 != 0.0 && std::abs(s1) <= 1.1e-3) {
      double r1 = 0.0;
      if (lands(s1, &r1)) return true;
      if ((r1 > 0.0) == (r0 < 0.0)) {
        bracket(0.0, r0, s1, r1);
        // The god object's line (a spring pulls along it), both probes on the wall (the contact
        // already pushes at the origin): where the wall is linear between them (one edge of the
        // assembly space) their secant lands on the root; the slope carried from the last
        // search does not where the line has turned since (a hand's tremor turns it every
        // tick). Not for the settle's searches (no spring): there it costs the clearance fits'
        // p99 a probe (18 instead of 17).
        if (spring > 0.0 && r0 + target > 0.0 && r1 != r0) {
          const double s2 = s1 - r1 * s1 / (r1 - r0);
          if (std::isfinite(s2) && s2 > lo && s2 < hi) {
            double r2 = 0.0;
            if (lands(s2, &r2)) return true;
            (r2 < 0.0 ? lo : hi) = s2;
            (r2 < 0.0 ? r_lo : r_hi) = r2;
          }
        }
      } else {
        // Short of the root (a wall that steepens as the part goes in: a texture's onset): the
        // secant through the origin and s1, 10 % further, is past the root on a convex
        // residual, a tight bracket where widening eightfold would jump far past; then widen
        // from the furthest point short of the root.
        double from = s1, r_from = r1;
        const double secant = s1 - 1.1 * r1 * s1 / (r1 - r0);
        if (r1 != r0 && std::isfinite(secant) && (secant - s1) * s1 > 0.0 &&
            std::abs(secant) <= 8.0 * std::abs(s1)) {
          double r2 = 0.0;
          if (lands(secant, &r2)) return true;
          if ((r2 > 0.0) == (r0 < 0.0)) {
            bracket(s1, r1, secant, r2);
          } else {
            from = secant;
            r_from = r2;
          }
        }
        if (!bracketed) {
          (r0 < 0.0 ? lo : hi) = from;
          (r0 < 0.0 ? r_lo : r_hi) = r_from;
          reach = 8.0 * std::abs(from);
        }
      }
    }
  }
  for (; reach <= 1.1e-3 && !bracketed; reach *= 8.0) {
    if (r0 < 0.0) {
      if (reach <= lo) continue;
      hi = reach;
      r_hi = residual(hi);
      bracketed = r_hi > 0.0;
      if (!bracketed) {
        lo = hi;
        r_lo = r_hi;
      }
    } else {
      if (-reach >= hi) continue;
      lo = -reach;
      r_lo = residual(lo);
      bracketed = r_lo < 0.0;
      if (!bracketed) {
        hi = lo;
        r_hi = r_lo;
      }
    }
  }
  if (!bracketed) return false;
  // A bracket often straddles the foot of a wall: flat (free motion along an edge of the assembly
  // space, or nothing touching yet) up to it, then the law's steep linear rise (eq. 9's spring,
  // kN/um). False position crawls along the flat side there (each step a probe); a Newton step
  // from the wall side, on the wall's slope by a 10 pm difference, lands on a linear wall's root
  // in one. Kept only when it improves the bracket.
  // A search around a last root (the god object's on a Winkler bed, whose wall is smooth) whose
  // bracket the contact pushes at both ends has no foot of a wall in it: false position from
  // the start (on a polygon's edges, where a bracket's ends may lie on different edges, the
  // Newton step from the wall side stays better: measured).
  constexpr double kWallProbe = 1e-11;
  const bool smooth = hint != nullptr && r_lo + (target - spring * lo) != 0.0;
  if (!smooth && hi - lo > 2.0 * kWallProbe) {
    const double r_in = residual(hi - kWallProbe);
    const double wall = (r_hi - r_in) / kWallProbe;
    if (r_in > 0.0 && r_in < r_hi) {
      hi -= kWallProbe;
      r_hi = r_in;
    }
    double step = hi - r_hi / wall;
    // Where that step lands on the wall again (the wall bends: a second edge of the assembly
    // space, or a kink of the texture's onset), secants through the last two points on the wall
    // follow it down; the first landing on the flat side ends them with a tight bracket.
    double wall_s = hi, wall_r = r_hi;
    for (int k = 0; k < 4 && wall > 0.0 && std::isfinite(step) && step > lo && step < hi; ++k) {
      double r = 0.0;
      if (lands(step, &r)) return true;
      if (r < 0.0) {
        lo = step;
        r_lo = r;
        break;
      }
      const double secant = (wall_r - r) / (wall_s - step);
      wall_s = hi = step;
      wall_r = r_hi = r;
      if (!(secant > 0.0)) break;
      step = hi - r_hi / secant;
    }
  }
  // 60 steps bound the tick's cost.
  *solution = IllinoisRoot(residual, lo, hi, r_lo, r_hi, tolerance, 60);
  learn();
  return true;
}

double ContactSearch::RadialStiffness(const MatingPose& pose, const MatingMotion& motion,
                                      const Wrench& wrench, int* evaluations) const noexcept {
  const Eigen::Vector2d force(wrench.force.x(), wrench.force.z());
  const double magnitude = force.norm();
  if (!(magnitude > 0.0) || !std::isfinite(magnitude)) return 0.0;
  // Forward difference one step deeper into the contact (against the force): the stiffness the
  // part meets where it is heading. 1 nm is far below every tolerance and texture height of a
  // fit (um) and far above the rounding of positions of a few mm (1e-19 m).
  constexpr double kStep = 1e-9;
  const Eigen::Vector2d into = -force / magnitude;
  MatingPose probe = pose;
  probe.offset += kStep * into;
  ContactState contact;
  analyzer_.Evaluate(probe, &contact);
  ++*evaluations;
  Wrench deeper;
  law_.Evaluate(contact, motion, &deeper);
  const Eigen::Vector2d deeper_force(deeper.force.x(), deeper.force.z());
  const double stiffness = (force - deeper_force).dot(into) / kStep;
  return std::isfinite(stiffness) && stiffness > 0.0 ? stiffness : 0.0;
}

}  // namespace fitfeel
