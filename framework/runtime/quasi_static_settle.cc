#include "framework/runtime/quasi_static_settle.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/root_finding.h"

namespace fitfeel {

bool QuasiStaticSettle::Settle(const Eigen::Vector2d& load, const MatingMotion& motion,
                               SettleMemory* memory, LawState* law_state,
                               StageOutput* out) const noexcept {
  const double weight = load.norm();
  if (!std::isfinite(weight)) return false;
  const Eigen::Vector2d down = load / weight;
  const Eigen::Vector2d across(-down.y(), down.x());
  StageOutput work = *out;
  // Nothing evaluated yet: no offset equals NaN, so the first probe anywhere evaluates.
  work.pose.offset.setConstant(std::numeric_limits<double>::quiet_NaN());
  // The part floats in both directions across the axis, as a shaft pressed by a compliant
  // gripper does: it sinks along the load until the contact carries it, then slides sideways to
  // where the contact pushes it no further (towards the assembly space's lowest corner, or the
  // energy-minimising axis of an interference fit), and sinks again (below: a Newton balance of
  // both directions, the sweeps as its fallback).
  // Starts from the previous tick's equilibrium: the part moves little between ticks.
  // Along the load the balance is solved to 1e-6 of the load. Sideways a push below 1 % of the
  // load is left: far under the ~7-10 % just-noticeable difference of force (haptics literature),
  // and on a near-circular assembly space (one edge per column) the resting part's sideways push
  // is below tan(pi/n) of the load anyway, so clearance fits need no sideways solve at all.
  const double along_tolerance = 1e-6 * weight;
  const double across_tolerance = 1e-2 * weight;
  // The searches along the load resolve a picometre of travel, no finer (their brackets end
  // there): where the last root's slope makes a picometre's force larger than the tolerance (a
  // press fit's kN/um against a load of a newton), that force is what they stop at.
  const double along_search_tolerance = std::max(along_tolerance, kPicometre * memory->along_slope);
  // Along the load the first probe is a Newton step from the last settle's slope.
  double* const along = &memory->along_slope;
  Eigen::Vector2d at = memory->offset;
  // Along the path by this tick's advance, where it continues the last one (the same direction,
  // at most four times as far: a robot's constant feed, a hand's smooth push); NaN before the
  // first settle compares false.
  const double advance = motion.depth - memory->depth;
  if (memory->smooth && advance * memory->depth_change > 0.0 &&
      std::abs(advance) <= 4.0 * std::abs(memory->depth_change)) {
    at += advance * memory->path;
  }
  double s = 0.0;
  // Where the last settle ended in interference on a stiffness that holds the part both ways (a
  // press fit) and the start is off balance sideways, the balance starts with the
  // two-dimensional step on it: a search along the load first would only find the along balance
  // that step moves off again (three evaluations). Balanced sideways, the search along the load
  // (its first probe this one) is the shorter way.
  bool stiff_start = memory->interference && HoldsBothWays(memory->stiffness);
  if (stiff_start) {
    const Eigen::Vector2d start = search_.ForceAt(at, motion, &work) + load;
    // (A part pulled out since meets no sideways push: the search below finds nothing carries it.)
    stiff_start = std::abs(start.dot(across)) > across_tolerance;
  } else if (memory->interference) {
    // Where the contact's stiffness comes in closed form (RadialJacobian), the Newton step on it
    // balances both directions from the first evaluation, a wall that holds the part one way only
    // (a pin resting on one side of its cone) included: no search along the load first.
    Eigen::Matrix2d unused;
    search_.ForceAt(at, motion, &work);
    stiff_start = search_.law().RadialJacobian(work.contact, &unused);
  }
  if (stiff_start) {
    // The Newton loop below starts here, from this evaluation.
  } else if (!search_.SolveAlong(at, down, weight, along_search_tolerance, motion, &work, &s, 0.0, along)) {
    // Nothing the model holds carries the load (a key's weight rests on the keyway's bottom,
    // which the planar model leaves out), but the part still floats sideways to where the walls
    // it touches balance, rather than being held off that balance by the device.
    // From the device's own pose; a part that touches nothing sideways stays where it is held.
    at = out->pose.offset;
    double t = 0.0;
    if (!search_.SolveAlong(at, across, 0.0, across_tolerance, motion, &work, &t) || t == 0.0) {
      out->contact_evaluations = work.contact_evaluations;  // what the attempt cost
      return false;
    }
    at += t * across;
  } else {
    at += s * down;
  }
  // Then both directions at once: Newton's method on the contact's 2x2 stiffness (by
  // differences), which brings a part resting on an inclined wall to its balance in a step or two
  // where alternating sweeps along and across zig-zag down the wall (tens of evaluations, the
  // tick's worst case); a direction without stiffness (a flat wall the part may slide along) is a
  // 1-D search along it to the next wall. The sweeps stay as the fallback.
  // A probe where the last one was (a root the 1-D search ended on) is answered from it.
  auto force_at = [&](const Eigen::Vector2d& x) { return search_.ForceAt(x, motion, &work); };
  // Along the load the searches stop at 1 pm of position where the tolerance is finer than a
  // picometre of the wall's travel (k h ~ 1e-3 N for kN/um walls): balanced is 1e-3 of the load
  // there, still far below what a hand resolves.
  auto balanced = [&](const Eigen::Vector2d& r) {
    return std::abs(r.dot(down)) <= 1e-3 * weight && std::abs(r.dot(across)) <= across_tolerance;
  };
  Eigen::Vector2d residual = force_at(at) + load;            // the unbalanced force on the part
  Eigen::Vector2d step_from = at, residual_from = residual;  // where the last step began
  for (int step = 0; step < kNewtonSteps && !balanced(residual); ++step) {
    // 10 pm: far inside the nanometre penetrations a load of newtons makes against kN/um walls,
    // far above rounding (k h ~ 1e-2 N against forces of 1 N).
    constexpr double kProbe = 1e-11;
    Eigen::Matrix2d k = memory->stiffness;  // stiffness, -d(force)/d(offset)
    // Where the analyzer and the law give the stiffness in closed form (the cone's and the
    // sphere's tables, ResistanceLaw::RadialJacobian), it is taken at every step: exact, where
    // the secants below lag a stiffness that grows as a taper is pressed (the pin's weight
    // balanced in three to four steps a tick) and differences cost two evaluations.
    Eigen::Matrix2d jacobian;
    const bool exact = search_.law().RadialJacobian(work.contact, &jacobian);
    if (exact) k = -jacobian;
    // Where the parts interfere, later steps correct the stiffness by the last step's secant
    // (Powell's symmetric update: the least change to k that is symmetric and maps the step to
    // the change of force it made) instead of two differences: a press fit's stiffness grows a few
    // per cent a tick as the interference does, and the step on the last tick's stiffness fell
    // short by as much; the secant is what the step measured.
    if (!exact && step > 0 && work.contact.interference) {
      const Eigen::Vector2d sx = at - step_from;
      const Eigen::Vector2d miss = -(residual - residual_from) - k * sx;  // (k_true - k) sx
      const double ss = sx.squaredNorm();
      if (ss > 0.0) {
        k += (miss * sx.transpose() + sx * miss.transpose()) / ss -
             (miss.dot(sx) / (ss * ss)) * (sx * sx.transpose());
      }
    }
    // The first step on the last tick's stiffness where the parts interfere and it holds the
    // part in both directions (a press fit: it changes little from tick to tick); by differences
    // in clearance (the part rests on one wall or in a corner of the assembly space, and which
    // changes from tick to tick), where a direction is nearly free, and on later steps without
    // interference or where the secant leaves the stiffness ill-conditioned.
    if (!exact && (!work.contact.interference || !HoldsBothWays(k))) {
      Eigen::Matrix2d d;  // d(force)/d(along, across)
      d.col(0) = (force_at(at + kProbe * down) + load - residual) / kProbe;
      d.col(1) = (force_at(at + kProbe * across) + load - residual) / kProbe;
      Eigen::Matrix2d basis;
      basis.col(0) = down;
      basis.col(1) = across;
      k = -d * basis.transpose();
    }
    memory->stiffness = k;
    Eigen::Vector2d term[2], free;
    if (!StiffNewtonTerms(k, residual, term, &free)) break;  // nothing holds: the sweeps
    const Eigen::Vector2d move = term[0] + term[1];
    step_from = at;
    residual_from = residual;
    at += move;
    const double slide = free.dot(residual);
    if (free.squaredNorm() > 0.0 && std::abs(slide) > along_tolerance) {
      // Along the wall the unbalanced force moves the part until the next wall takes it.
      const Eigen::Vector2d axis = slide > 0.0 ? free : Eigen::Vector2d(-free);
      const double tolerance =
          std::max(along_tolerance, across_tolerance * std::abs(axis.dot(across)));
      double t = 0.0;
      if (search_.SolveAlong(at, axis, load.dot(axis), tolerance, motion, &work, &t)) at += t * axis;
    }
    residual = force_at(at) + load;
  }
  for (int sweep = 0; sweep < 4 && !balanced(residual); ++sweep) {
    double t = 0.0;
    if (!search_.SolveAlong(at, across, 0.0, across_tolerance, motion, &work, &t) || t == 0.0) break;
    at += t * across;
    if (!search_.SolveAlong(at, down, weight, along_search_tolerance, motion, &work, &s, 0.0, along)) {
      break;
    }
    at += s * down;
  }
  // The Newton steps stop at 1e-3 of the load along it; where a picometre allows finer, the
  // along search (a Newton step from its slope, usually one evaluation) finishes to 1e-6. Where
  // the force left is less than a picometre's travel on the last stiffness makes, the search
  // could only probe within that picometre.
  const double along_stiffness = down.dot(memory->stiffness * down);
  if (std::abs(residual.dot(down)) >
          std::max(along_search_tolerance, kPicometre * along_stiffness) &&
      search_.SolveAlong(at, down, weight, along_search_tolerance, motion, &work, &s, 0.0, along)) {
    at += s * down;
  }
  // Leave pose, contact and wrench consistent at the settled offset (the contact is usually the
  // last probe's already).
  search_.ForceAt(at, motion, &work);
  // The next tick's start: one Newton step on the last known stiffness from here, on what is
  // left unbalanced (within the tolerances, so at most a fraction of a nanometre to a few).
  Eigen::Vector2d next = at;
  if (memory->stiffness != Eigen::Matrix2d::Zero()) {
    const Eigen::Vector2d left =
        Eigen::Vector2d(work.wrench.force.x(), work.wrench.force.z()) + load;
    Eigen::Vector2d term[2], free;
    if (StiffNewtonTerms(memory->stiffness, left, term, &free)) {
      next += term[0];
      next += term[1];
    }
  }
  work.wrench.SetZero();
  if (!work.contact.engaged) *law_state = LawState{};  // as DoEvaluate does unsettled
  search_.law().Evaluate(work.contact, motion, law_state, &work.wrench);
  out->elastic = search_.law().CheckElasticLimit(work.contact);
  out->pose = work.pose;
  out->contact = work.contact;
  out->wrench = work.wrench;
  out->contact_evaluations = work.contact_evaluations;
  memory->offset = next;
  if (advance != 0.0 && std::isfinite(advance)) {
    const Eigen::Vector2d path = (at - memory->root) / advance;
    memory->smooth = (path - memory->path).norm() <= 0.5 * path.norm();
    memory->path = path;
    memory->depth_change = advance;
  }
  memory->root = at;
  memory->depth = motion.depth;
  memory->interference = work.contact.interference;
  return true;
}

}  // namespace fitfeel
