#include "framework/runtime/constrained_stage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "framework/core/error.h"
#include "framework/runtime/positioning_stage.h"

namespace fitfeel {
namespace {

struct ConstrainedState final : StageState {
  // Where the last settled tick left the part: the next settle's starting point.
  Eigen::Vector2d last_settled{0.0, 0.0};
  // The law's state (friction junctions), advanced once per tick at the rendered pose.
  LawState law;
};

}  // namespace

ConstrainedStage::ConstrainedStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law)
    : analyzer_(analyzer), law_(law) {
  if (!analyzer.prepared()) throw UserError("constrained stage needs a prepared contact analyzer");
}

std::unique_ptr<StageState> ConstrainedStage::DoMakeState() const {
  return std::make_unique<ConstrainedState>();
}

void ConstrainedStage::DoEvaluate(const DeviceState& device, StageState* state,
                                  StageOutput* out) const noexcept {
  out->pose = MatingPoseOf(device);
  out->contact = ContactState{};
  out->elastic = ElasticLimitCheck{};
  analyzer_.Evaluate(out->pose, &out->contact);
  MatingMotion motion;
  motion.velocity = device.velocity;
  motion.angular_velocity = device.angular_velocity;
  motion.depth = out->pose.depth;
  motion.angle = out->pose.angle;
  out->wrench.SetZero();
  out->next = out->pose.depth < 0.0 ? StageId::kPositioning : StageId::kConstrained;
  auto* run = static_cast<ConstrainedState*>(state);
  // Out of engagement (withdrawn, about to hand back to positioning) the junctions let go, so a
  // later re-entry forms its contact afresh rather than at a stale anchor.
  if (!out->contact.engaged) run->law = LawState{};
  const bool settle = device.settle_load.squaredNorm() > 0.0;
  if (settle) law_.Evaluate(out->contact, motion, &out->wrench);  // the search's start
  if (settle && Settle(device.settle_load, motion, &run->last_settled, &run->law, out)) {
    // Settled: the device integrates no radial motion, so it needs neither stiffness nor gap.
    out->stiffness = 0.0;
    out->gap = std::numeric_limits<double>::infinity();
    out->gap_direction.setZero();
    return;
  }
  out->wrench.SetZero();
  law_.Evaluate(out->contact, motion, &run->law, &out->wrench);
  out->elastic = law_.CheckElasticLimit(out->contact);
  out->stiffness = RadialStiffness(out->pose, motion, out->wrench);
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

bool ConstrainedStage::SolveAlong(const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                                  double target, double tolerance, const MatingMotion& motion,
                                  StageOutput* work, double* solution) const noexcept {
  // Support the contact gives along -axis with the part at origin + s * axis, minus the target:
  // negative while the part would move further along the axis. The laws' radial force grows
  // monotonically with the offset into a wall (eq. 9's spring, eqs. 10-12's interference), so
  // the root is unique up to a flat stretch of free motion, where any point is an equilibrium.
  auto residual = [&](double s) {
    work->pose.offset = origin + s * axis;
    analyzer_.Evaluate(work->pose, &work->contact);
    work->wrench.SetZero();
    law_.Evaluate(work->contact, motion, &work->wrench);
    return -(work->wrench.force.x() * axis.x() + work->wrench.force.z() * axis.y()) - target;
  };
  // The root is usually within a few um of the origin (the previous tick's equilibrium): check
  // the origin first, then bracket on the side the residual points to, starting 1 um away and
  // widening eightfold up to 1 mm: beyond every fit's clearance and interference (ISO 286 limits
  // of parts up to 500 mm stay below 1 mm) and within every bore this framework models.
  const double r0 = residual(0.0);
  if (std::abs(r0) <= tolerance) {
    *solution = 0.0;
    return true;
  }
  double lo = 0.0, hi = 0.0, r_lo = r0, r_hi = r0;
  bool bracketed = false;
  for (double reach = 1e-6; reach <= 1.1e-3 && !bracketed; reach *= 8.0) {
    if (r0 < 0.0) {
      hi = reach;
      r_hi = residual(hi);
      bracketed = r_hi > 0.0;
      if (!bracketed) {
        lo = hi;
        r_lo = r_hi;
      }
    } else {
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
  // Illinois false position: superlinear on the piecewise-linear laws, never leaves the bracket;
  // stops at 1 pm of position or at the tolerance; 60 iterations bound the tick's cost.
  double s = hi;
  int side = 0;
  for (int k = 0; k < 60 && hi - lo > 1e-12; ++k) {
    s = (lo * r_hi - hi * r_lo) / (r_hi - r_lo);
    const double r = residual(s);
    if (std::abs(r) <= tolerance) break;
    if (r > 0.0) {
      hi = s;
      r_hi = r;
      if (side == 1) r_lo *= 0.5;
      side = 1;
    } else {
      lo = s;
      r_lo = r;
      if (side == -1) r_hi *= 0.5;
      side = -1;
    }
  }
  *solution = s;
  return true;
}

bool ConstrainedStage::Settle(const Eigen::Vector2d& load, const MatingMotion& motion,
                              Eigen::Vector2d* last_settled, LawState* law_state,
                              StageOutput* out) const noexcept {
  const double weight = load.norm();
  if (!std::isfinite(weight)) return false;
  const Eigen::Vector2d down = load / weight;
  const Eigen::Vector2d across(-down.y(), down.x());
  StageOutput work = *out;
  // The part floats in both directions across the axis, as a shaft pressed by a compliant
  // gripper does: it sinks along the load until the contact carries it, then slides sideways to
  // where the contact pushes it no further (towards the assembly space's lowest corner, or the
  // energy-minimising axis of an interference fit), and sinks again. Under interference the
  // force is a spring about that axis and one sweep is exact; in clearance a few sweeps bring a
  // part resting on a wall to its corner.
  // Starts from the previous tick's equilibrium: the part moves little between ticks.
  // Along the load the balance is solved to 1e-6 of the load. Sideways a push below 1 % of the
  // load is left: far under the ~7-10 % just-noticeable difference of force (haptics literature),
  // and on a near-circular assembly space (one edge per column) the resting part's sideways push
  // is below tan(pi/n) of the load anyway, so clearance fits need no sideways solve at all.
  const double along_tolerance = 1e-6 * weight;
  const double across_tolerance = 1e-2 * weight;
  Eigen::Vector2d at = *last_settled;
  double s = 0.0;
  if (!SolveAlong(at, down, weight, along_tolerance, motion, &work, &s)) {
    // Nothing the model holds carries the load (a key's weight rests on the keyway's bottom,
    // which the planar model leaves out), but the part still floats sideways to where the walls
    // it touches balance, rather than being held off that balance by the device.
    // From the device's own pose; a part that touches nothing sideways stays where it is held.
    at = out->pose.offset;
    double t = 0.0;
    if (!SolveAlong(at, across, 0.0, across_tolerance, motion, &work, &t) || t == 0.0) {
      return false;
    }
    at += t * across;
  } else {
    at += s * down;
  }
  for (int sweep = 0; sweep < 4; ++sweep) {
    double t = 0.0;
    if (!SolveAlong(at, across, 0.0, across_tolerance, motion, &work, &t) || t == 0.0) break;
    at += t * across;
    if (!SolveAlong(at, down, weight, along_tolerance, motion, &work, &s)) break;
    at += s * down;
  }
  // Leave pose, contact and wrench consistent at the settled offset.
  work.pose.offset = at;
  analyzer_.Evaluate(work.pose, &work.contact);
  work.wrench.SetZero();
  law_.Evaluate(work.contact, motion, law_state, &work.wrench);
  out->elastic = law_.CheckElasticLimit(work.contact);
  out->pose = work.pose;
  out->contact = work.contact;
  out->wrench = work.wrench;
  *last_settled = at;
  return true;
}

double ConstrainedStage::RadialStiffness(const MatingPose& pose, const MatingMotion& motion,
                                         const Wrench& wrench) const noexcept {
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
  Wrench deeper;
  law_.Evaluate(contact, motion, &deeper);
  const Eigen::Vector2d deeper_force(deeper.force.x(), deeper.force.z());
  const double stiffness = (force - deeper_force).dot(into) / kStep;
  return std::isfinite(stiffness) && stiffness > 0.0 ? stiffness : 0.0;
}

}  // namespace fitfeel
