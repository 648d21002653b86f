#include "framework/runtime/god_object.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/root_finding.h"

namespace fitfeel {

void GodObject::FollowDevice(const MatingMotion& device_motion, GodObjectMemory* god,
                             LawState* law_state, StageOutput* out) const noexcept {
  const double k = stiffness_;
  const Eigen::Vector2d held = out->pose.offset;
  const double held_depth = out->pose.depth;
  MatingMotion motion = device_motion;
  StageOutput work = *out;
  // Across the axis, at `depth`: where the contact's push balances the spring k (held - p). The
  // contact is far stiffer than the spring (kN/um against kN/m), so the part sits on the edge of
  // the positions its axis may take (the assembly space, or the energy-minimising axis under
  // interference) within nanometres: first that edge point, where the analyzer anchors the
  // device's pose (pose - penetration * direction, repeated from there, since between two depth
  // steps the anchor blends two spaces' projections and moves a little); then, on the line from
  // it to the device, the balance of the law's push and the spring (found as the settling's
  // roots are; a push of 1e-4 N, or 1e-6 of the pull, is far below what a hand resolves), which
  // puts the part just as far into the wall as the law needs to carry the pull.
  auto anchor_of = [&](const Eigen::Vector2d& offset) {
    work.pose.offset = offset;
    search_.analyzer().Evaluate(work.pose, &work.contact);
    ++work.contact_evaluations;
    return Eigen::Vector2d(offset - work.contact.penetration * work.contact.penetration_direction);
  };
  // On a Winkler bed whose stiffness the law gives in closed form (the cone's and the sphere's
  // tables), Newton's method from where the last balance left the part: the part moves
  // nanometres from tick to tick (a wall of kN/um against a spring of kN/m) while the device
  // moves micrometres (a hand's tremor: tenths of a newton of the spring's pull a tick), and on
  // the exact stiffness the balance converges quadratically, in two or three evaluations where
  // the searches below take seven to ten. Three steps at most; then those searches.
  auto newton_on_bed = [&](AcrossMemory* memory, Eigen::Vector2d* part) {
    Eigen::Vector2d p = memory->bed_part;
    if (!p.allFinite()) return false;
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector2d r = search_.ProbeAt(p, motion, &work) + k * (held - p);
      if (r.norm() <= std::max(1e-4, 1e-6 * k * (held - p).norm())) {
        *part = p;
        return true;
      }
      Eigen::Matrix2d jacobian;
      if (i == 3 || !search_.law().RadialJacobian(work.contact, &jacobian)) break;
      jacobian.diagonal().array() -= k;  // the spring's pull falls as the part nears the device
      const Eigen::Vector2d step = -jacobian.partialPivLu().solve(r);
      if (!step.allFinite()) break;
      p += step;
    }
    return false;
  };
  auto across = [&](double depth, AcrossMemory* memory) {
    work.pose.depth = depth;
    motion.depth = depth;
    if (Eigen::Vector2d part; newton_on_bed(memory, &part)) {
      memory->bed_part = part;
      return part;
    }
    memory->bed_part.setConstant(std::numeric_limits<double>::quiet_NaN());
    Eigen::Vector2d edge = anchor_of(held);
    Eigen::Vector2d part = held;
    const bool bed = edge == held;
    if (bed) {
      // No assembly space in the analyzer's answer (a Winkler bed of cells, as the cone's and the
      // sphere's): free if the law does not push, else balanced along its push, from the device
      // outwards, where the push falls and the spring's pull rises.
      work.wrench.SetZero();
      search_.law().Evaluate(work.contact, motion, &work.wrench);
      const Eigen::Vector2d push(work.wrench.force.x(), work.wrench.force.z());
      const double magnitude = push.norm();
      if (!(magnitude > 0.0) || !std::isfinite(magnitude)) return held;  // free: it follows
      const Eigen::Vector2d into = -push / magnitude;
      double s = 0.0;
      const double tolerance =
          std::max({1e-4, 1e-6 * magnitude, kPicometre * memory->across_slope});
      if (!search_.SolveAlong(held, into, 0.0, tolerance, motion, &work, &s, k,
                              &memory->across_slope, &memory->across_root)) {
        return held;
      }
      memory->across_root = s;
      part = held + std::min(s, 0.0) * into;
    } else {
      // The repetition contracts by a near-constant factor (0.6-0.7 between two depth steps'
      // spaces): after two steps along one line, Aitken's extrapolation (Irons and Tuck's vector
      // form) lands on the fixed point of that affine map, and the next evaluation checks it.
      Eigen::Vector2d last_step = Eigen::Vector2d::Zero();
      for (int i = 0; i < 8; ++i) {
        Eigen::Vector2d next = anchor_of(edge);
        const Eigen::Vector2d step = next - edge;
        const bool settled = step.norm() <= 1e-12;
        const Eigen::Vector2d bend = step - last_step;
        last_step = step;
        if (!settled && i > 0 && bend.squaredNorm() > 0.0) {
          // step . bend / |bend|^2 = rho / (rho - 1) for a contraction rho in (0, 0.99].
          const double ratio = step.dot(bend) / bend.squaredNorm();
          if (ratio < 0.0 && ratio >= -99.0) {
            next -= ratio * step;
            last_step.setZero();  // the next extrapolation wants two new steps
          }
        }
        edge = next;
        if (settled) break;
      }
      // Those evaluations took the contact only, not the law's push: no probe to reuse.
      work.pose.offset.setConstant(std::numeric_limits<double>::quiet_NaN());
      const Eigen::Vector2d way = held - edge;
      const double reach = way.norm();
      if (!(reach > 0.0) || !std::isfinite(reach)) return held;
      const Eigen::Vector2d into = way / reach;
      const double tolerance = std::max({1e-4, 1e-6 * k * reach, kPicometre * memory->line_slope});
      double s = 0.0;
      // The root lies nanometres into the wall from the edge, where the wall's stiffness along
      // the line changes little from tick to tick: a Newton step on the last balance's slope
      // lands on it (the last root itself is no start: the edge moves with the device).
      if (!search_.SolveAlong(edge, into, k * reach, tolerance, motion, &work, &s, k,
                              &memory->line_slope)) {
        return edge;
      }
      // s < 0 where the edge found is still inside the wall: the anchor converges slowly where
      // the part has barely entered (it blends the free entrance with the first row's space).
      part = edge + std::min(s, reach) * into;
    }
    // That line is the wall's normal only where the edge is the device's nearest point of the
    // space; where it is not (the anchor blends two depth steps' spaces, or the space is a sliver
    // off the axis), the law's push at the balance has a part across the line, and its size,
    // the normal force friction takes, exceeds the spring's pull that the wall carries. Along
    // the push itself the part then backs out of the wall (nanometres) until the push equals
    // the pull: the wall carries what the hand presses, no more.
    // The solve's last evaluation is usually at the part already (at this depth: every
    // evaluation above was).
    search_.ForceAt(part, motion, &work);
    const Eigen::Vector2d push(work.wrench.force.x(), work.wrench.force.z());
    const double pull = k * (held - part).norm();
    const double magnitude = push.norm();
    if (magnitude > 1.01 * pull + 1e-4 && std::isfinite(magnitude)) {
      const Eigen::Vector2d wall = -push / magnitude;
      double t = 0.0;
      // With the memory only on a Winkler bed (as above; on a polygon's edge it costs more than
      // it saves, measured).
      const double tolerance =
          std::max({1e-4, 1e-3 * pull, bed ? kPicometre * memory->back_slope : 0.0});
      if (search_.SolveAlong(part, wall, pull, tolerance, motion, &work, &t, 0.0,
                             bed ? &memory->back_slope : nullptr,
                             bed ? &memory->back_root : nullptr)) {
        if (bed) memory->back_root = t;
        if (t < 0.0) part += t * wall;
      }
    }
    // A balance on a bed with a closed-form stiffness starts the next tick's Newton steps.
    if (Eigen::Matrix2d unused; bed && search_.law().RadialJacobian(work.contact, &unused)) {
      memory->bed_part = part;
    }
    return part;
  };
  // The balance across the axis at the device's depth serves every depth tried along it: the
  // part goes no deeper than the device, and where the bore narrows ahead that balance already
  // has it clear of the narrowing (a balance taken at the part's own depth would run it into
  // the step and hold it there as if it were jammed).
  Eigen::Vector2d at = across(held_depth, &god->at_device);
  // Along the axis: where the law's resistance (stick-slip junctions, probed from the run's state
  // without advancing it) balances the spring k (held - y), the part at that balance across. The
  // resistance falls monotonically as the part goes deeper (a junction's spring, then the
  // kinetic level, against the way in), so the root between the part's last depth and the
  // device's is unique.
  auto axial = [&](double depth) {
    work.pose.depth = depth;
    work.pose.offset = at;
    motion.depth = depth;
    search_.analyzer().Evaluate(work.pose, &work.contact);
    ++work.contact_evaluations;
    LawState probe = *law_state;
    if (!work.contact.engaged) probe = LawState{};
    work.wrench.SetZero();
    search_.law().Evaluate(work.contact, motion, &probe, &work.wrench);
    return k * (held_depth - depth) + work.wrench.force.y();
  };
  double depth = held_depth;
  bool lags = false;
  const double at_device = axial(held_depth);
  const bool couple = work.contact.couple_normal > 0.0;
  constexpr double kAxialTolerance = 1e-4;  // N, as across
  if (std::abs(at_device) > kAxialTolerance) {
    double lo = god->part_depth, hi = held_depth;
    double g_lo = axial(lo), g_hi = at_device;
    // A compliant holder's part forced into line meets a resistance that rises with depth (the
    // couple grows as it goes in), which may balance the spring more than once on the way: the
    // part stops at the first balance, so the bracket is narrowed to the first of eight parts of
    // it that changes sign. Elsewhere the resistance falls with depth and the root is unique.
    const double spring_lo = k * (held_depth - lo);
    if (couple && g_lo * g_hi < 0.0 && -g_hi > spring_lo - g_lo) {
      constexpr int kParts = 8;
      const double width = (hi - lo) / kParts;
      for (int i = 1; i < kParts; ++i) {
        const double mid = lo + width;
        const double g_mid = axial(mid);
        if (g_lo * g_mid <= 0.0) {
          hi = mid;
          g_hi = g_mid;
          break;
        }
        lo = mid;
        g_lo = g_mid;
      }
    }
    if (g_lo * g_hi < 0.0) {
      depth = IllinoisRoot(axial, lo, hi, g_lo, g_hi, kAxialTolerance, 40);
    } else {
      depth = std::abs(g_lo) < std::abs(g_hi) ? lo : hi;
    }
    // The balance across at the device's depth holds within 10 um of it (the spaces change over
    // rows of 0.5 mm and more): taken anew only where the part lags further. Its line starts on
    // the part's own slope where the part lagged on the last tick too (a press fit held back by
    // its friction), else on this tick's at the device's depth (the part's own is from its last
    // lag, often hundreds of ticks ago): a hand's insertion of a clearance fit, largest tick
    // 31 contact evaluations instead of 34. (Repeating the edge from that balance instead of from
    // the device would save two more there and cost another scene's worst tick 107, not 70.)
    lags = std::abs(depth - held_depth) > 1e-5;
    if (lags) {
      if (!god->lagged) god->at_part.line_slope = god->at_device.line_slope;
      at = across(depth, &god->at_part);
    }
  }
  god->lagged = lags;
  god->part = at;
  god->part_depth = depth;
  out->pose.offset = at;
  out->pose.depth = depth;
  motion.depth = depth;
  // The last probe's contact where it was taken at the part's pose (the same numbers).
  out->contact_evaluations = work.contact_evaluations;
  if (work.pose.offset == at && work.pose.depth == depth && work.pose.angle == out->pose.angle) {
    out->contact = work.contact;
  } else {
    search_.analyzer().Evaluate(out->pose, &out->contact);
    ++out->contact_evaluations;
  }
  // Out of engagement (withdrawn) the junctions let go, as in the rigid case.
  if (!out->contact.engaged) *law_state = LawState{};
  out->wrench.SetZero();
  search_.law().Evaluate(out->contact, motion, law_state, &out->wrench);
  out->elastic = search_.law().CheckElasticLimit(out->contact);
  // The device feels the spring that pulls the part towards it; the part sits where the
  // contact balances it, so the two agree to within the solves' tolerances.
  out->wrench.force.x() = k * (at.x() - held.x());
  out->wrench.force.y() = k * (depth - held_depth);
  out->wrench.force.z() = k * (at.y() - held.y());
  out->stiffness = (at == held && depth == held_depth) ? 0.0 : k;
  out->next = depth < 0.0 ? StageId::kPositioning : StageId::kConstrained;
  SetGap(out);
}

}  // namespace fitfeel
