#include "framework/runtime/constrained_stage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <Eigen/Eigenvalues>

#include "framework/core/error.h"
#include "framework/runtime/positioning_stage.h"

namespace fitfeel {
namespace {

struct ConstrainedState final : StageState {
  // Where the last settled tick left the part (the next settle's starting point), and its slope.
  ConstrainedStage::SettleMemory settle;
  // The law's state (friction junctions), advanced once per tick at the rendered pose.
  LawState law;
  // The god object's offset and mating depth (Options::proxy_stiffness finite).
  Eigen::Vector2d part{0.0, 0.0};
  double part_depth = 0.0;
  // The god object's balances across the axis: at the device's depth, and at the part's own
  // where it lags the device (a jammed part: both are solved every tick, each from its own
  // memory; one shared memory warm-started each from the other's root, 10-12 evaluations each).
  ConstrainedStage::AcrossMemory at_device;
  ConstrainedStage::AcrossMemory at_part;
  bool lagged = false;  // the last tick solved the balance at the part's own depth
};

// The finest travel the 1-D searches resolve (IllinoisRoot's brackets end there). Where a
// tolerance in force is finer than what a picometre of travel makes on the last root's slope, a
// search stops at that force instead: it could only probe within the picometre.
constexpr double kPicometre = 1e-12;

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
bool HoldsBothWays(const Eigen::Matrix2d& k) noexcept {
  const double det = k.determinant(), trace = k.trace();
  return trace > 0.0 && det > 1e-2 * trace * trace;
}

// The Newton step of a 2x2 contact stiffness k (-dF/d(offset), symmetrised) against the
// unbalanced force `residual`, one term per eigen-direction that has stiffness (an eigenvalue
// above 1e-6 of the largest; zero for a direction without, which `free` receives, zero if none).
// False, with nothing written, when nothing holds the part (no positive finite eigenvalue).
bool StiffNewtonTerms(const Eigen::Matrix2d& k, const Eigen::Vector2d& residual,
                      Eigen::Vector2d term[2], Eigen::Vector2d* free) noexcept {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(0.5 * (k + k.transpose()));
  const double largest = eig.eigenvalues().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest)) return false;
  free->setZero();
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector2d v = eig.eigenvectors().col(i);
    const double lambda = eig.eigenvalues()[i];
    term[i].setZero();
    if (lambda > 1e-6 * largest) {
      term[i] = (v.dot(residual) / lambda) * v;
    } else {
      *free = v;
    }
  }
  return true;
}

}  // namespace

ConstrainedStage::ConstrainedStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law)
    : ConstrainedStage(analyzer, law, Options{}) {}

ConstrainedStage::ConstrainedStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law,
                                   const Options& options)
    : analyzer_(analyzer), law_(law), options_(options) {
  if (!analyzer.prepared()) throw UserError("constrained stage needs a prepared contact analyzer");
  if (!std::isfinite(options.depth_origin) || !(options.proxy_stiffness > 0.0)) {
    throw UserError(
        "constrained stage: the depth origin must be finite and the proxy stiffness > 0");
  }
}

std::unique_ptr<StageState> ConstrainedStage::DoMakeState() const {
  return std::make_unique<ConstrainedState>();
}

void ConstrainedStage::DoEvaluate(const DeviceState& device, StageState* state,
                                  StageOutput* out) const noexcept {
  if (options_.moving == Role::kInner) {
    EvaluateInAnalyzerFrame(device, state, out);
    return;
  }
  // The reflection in z (AnalyzerPose) of every vector read and written; the twist stays, so the
  // orientation does too.
  const Eigen::Vector3d reflect(1.0, 1.0, -1.0);
  DeviceState relative = device;
  relative.position = device.position.cwiseProduct(reflect);
  relative.velocity = device.velocity.cwiseProduct(reflect);
  relative.angular_velocity = device.angular_velocity.cwiseProduct(reflect);
  relative.load.y() = -device.load.y();
  out->pose = AnalyzerPose(out->pose, options_.moving);  // the hand-over's
  EvaluateInAnalyzerFrame(relative, state, out);
  out->pose = AnalyzerPose(out->pose, options_.moving);
  out->wrench.force = out->wrench.force.cwiseProduct(reflect);
  out->wrench.torque = out->wrench.torque.cwiseProduct(reflect);
  out->gap_direction.y() = -out->gap_direction.y();
  SceneContact(&out->contact, options_.moving);
}

void ConstrainedStage::EvaluateInAnalyzerFrame(const DeviceState& device, StageState* state,
                                               StageOutput* out) const noexcept {
  auto* run = static_cast<ConstrainedState*>(state);
  // Handed over by the positioning stage: the part is where that stage left it.
  if (out->stage != StageId::kConstrained) {
    run->part = out->pose.offset;
    run->part_depth = out->pose.depth;
  }
  out->pose = MatingPoseOf(device);
  out->pose.depth -= options_.depth_origin;
  out->contact = ContactState{};
  out->elastic = ElasticLimitCheck{};
  MatingMotion motion;
  motion.velocity = device.velocity;
  motion.angular_velocity = device.angular_velocity;
  motion.depth = out->pose.depth;
  motion.angle = out->pose.angle;
  const bool settle = device.load.squaredNorm() > 0.0;
  if (!settle && std::isfinite(options_.proxy_stiffness)) {
    FollowDevice(motion, state, out);
    return;
  }
  out->wrench.SetZero();
  out->next = out->pose.depth < 0.0 ? StageId::kPositioning : StageId::kConstrained;
  // The settle starts where the last one left the part, not at the device's pose: the contact
  // there is evaluated only when nothing carries the load.
  if (settle && Settle(device.load, motion, &run->settle, &run->law, out)) {
    // Settled: nothing integrates the part's radial motion, so neither stiffness nor gap is needed.
    out->stiffness = 0.0;
    out->gap = std::numeric_limits<double>::infinity();
    out->gap_direction.setZero();
    return;
  }
  analyzer_.Evaluate(out->pose, &out->contact);
  ++out->contact_evaluations;
  // Out of engagement (withdrawn, about to hand back to positioning) the junctions let go, so a
  // later re-entry forms its contact afresh rather than at a stale anchor.
  if (!out->contact.engaged) run->law = LawState{};
  law_.Evaluate(out->contact, motion, &run->law, &out->wrench);
  out->elastic = law_.CheckElasticLimit(out->contact);
  out->stiffness = RadialStiffness(out->pose, motion, out->wrench, &out->contact_evaluations);
  SetGap(out);
}

void ConstrainedStage::SetGap(StageOutput* out) noexcept {
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

Eigen::Vector2d ConstrainedStage::ProbeAt(const Eigen::Vector2d& offset, const MatingMotion& motion,
                                          StageOutput* work) const noexcept {
  work->pose.offset = offset;
  analyzer_.Evaluate(work->pose, &work->contact);
  ++work->contact_evaluations;
  work->wrench.SetZero();
  law_.Evaluate(work->contact, motion, &work->wrench);
  return {work->wrench.force.x(), work->wrench.force.z()};
}

Eigen::Vector2d ConstrainedStage::ForceAt(const Eigen::Vector2d& offset, const MatingMotion& motion,
                                          StageOutput* work) const noexcept {
  if (work->pose.offset == offset) return {work->wrench.force.x(), work->wrench.force.z()};
  return ProbeAt(offset, motion, work);
}

bool ConstrainedStage::SolveAlong(const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
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

bool ConstrainedStage::Settle(const Eigen::Vector2d& load, const MatingMotion& motion,
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
    const Eigen::Vector2d start = ForceAt(at, motion, &work) + load;
    // (A part pulled out since meets no sideways push: the search below finds nothing carries it.)
    stiff_start = std::abs(start.dot(across)) > across_tolerance;
  } else if (memory->interference) {
    // Where the contact's stiffness comes in closed form (RadialJacobian), the Newton step on it
    // balances both directions from the first evaluation, a wall that holds the part one way only
    // (a pin resting on one side of its cone) included: no search along the load first.
    Eigen::Matrix2d unused;
    ForceAt(at, motion, &work);
    stiff_start = law_.RadialJacobian(work.contact, &unused);
  }
  if (stiff_start) {
    // The Newton loop below starts here, from this evaluation.
  } else if (!SolveAlong(at, down, weight, along_search_tolerance, motion, &work, &s, 0.0, along)) {
    // Nothing the model holds carries the load (a key's weight rests on the keyway's bottom,
    // which the planar model leaves out), but the part still floats sideways to where the walls
    // it touches balance, rather than being held off that balance by the device.
    // From the device's own pose; a part that touches nothing sideways stays where it is held.
    at = out->pose.offset;
    double t = 0.0;
    if (!SolveAlong(at, across, 0.0, across_tolerance, motion, &work, &t) || t == 0.0) {
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
  auto force_at = [&](const Eigen::Vector2d& x) { return ForceAt(x, motion, &work); };
  // Along the load the searches stop at 1 pm of position where the tolerance is finer than a
  // picometre of the wall's travel (k h ~ 1e-3 N for kN/um walls): balanced is 1e-3 of the load
  // there, still far below what a hand resolves.
  auto balanced = [&](const Eigen::Vector2d& r) {
    return std::abs(r.dot(down)) <= 1e-3 * weight && std::abs(r.dot(across)) <= across_tolerance;
  };
  Eigen::Vector2d residual = force_at(at) + load;            // the unbalanced force on the part
  Eigen::Vector2d step_from = at, residual_from = residual;  // where the last step began
  for (int step = 0; step < kSettleNewtonSteps && !balanced(residual); ++step) {
    // 10 pm: far inside the nanometre penetrations a load of newtons makes against kN/um walls,
    // far above rounding (k h ~ 1e-2 N against forces of 1 N).
    constexpr double kProbe = 1e-11;
    Eigen::Matrix2d k = memory->stiffness;  // stiffness, -d(force)/d(offset)
    // Where the analyzer and the law give the stiffness in closed form (the cone's and the
    // sphere's tables, ResistanceLaw::RadialJacobian), it is taken at every step: exact, where
    // the secants below lag a stiffness that grows as a taper is pressed (the pin's weight
    // balanced in three to four steps a tick) and differences cost two evaluations.
    Eigen::Matrix2d jacobian;
    const bool exact = law_.RadialJacobian(work.contact, &jacobian);
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
      if (SolveAlong(at, axis, load.dot(axis), tolerance, motion, &work, &t)) at += t * axis;
    }
    residual = force_at(at) + load;
  }
  for (int sweep = 0; sweep < 4 && !balanced(residual); ++sweep) {
    double t = 0.0;
    if (!SolveAlong(at, across, 0.0, across_tolerance, motion, &work, &t) || t == 0.0) break;
    at += t * across;
    if (!SolveAlong(at, down, weight, along_search_tolerance, motion, &work, &s, 0.0, along)) {
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
      SolveAlong(at, down, weight, along_search_tolerance, motion, &work, &s, 0.0, along)) {
    at += s * down;
  }
  // Leave pose, contact and wrench consistent at the settled offset (the contact is usually the
  // last probe's already).
  ForceAt(at, motion, &work);
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
  law_.Evaluate(work.contact, motion, law_state, &work.wrench);
  out->elastic = law_.CheckElasticLimit(work.contact);
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

void ConstrainedStage::FollowDevice(const MatingMotion& device_motion, StageState* state,
                                    StageOutput* out) const noexcept {
  auto* run = static_cast<ConstrainedState*>(state);
  const double k = options_.proxy_stiffness;
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
    analyzer_.Evaluate(work.pose, &work.contact);
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
      const Eigen::Vector2d r = ProbeAt(p, motion, &work) + k * (held - p);
      if (r.norm() <= std::max(1e-4, 1e-6 * k * (held - p).norm())) {
        *part = p;
        return true;
      }
      Eigen::Matrix2d jacobian;
      if (i == 3 || !law_.RadialJacobian(work.contact, &jacobian)) break;
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
      law_.Evaluate(work.contact, motion, &work.wrench);
      const Eigen::Vector2d push(work.wrench.force.x(), work.wrench.force.z());
      const double magnitude = push.norm();
      if (!(magnitude > 0.0) || !std::isfinite(magnitude)) return held;  // free: it follows
      const Eigen::Vector2d into = -push / magnitude;
      double s = 0.0;
      const double tolerance =
          std::max({1e-4, 1e-6 * magnitude, kPicometre * memory->across_slope});
      if (!SolveAlong(held, into, 0.0, tolerance, motion, &work, &s, k, &memory->across_slope,
                      &memory->across_root)) {
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
      if (!SolveAlong(edge, into, k * reach, tolerance, motion, &work, &s, k,
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
    ForceAt(part, motion, &work);
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
      if (SolveAlong(part, wall, pull, tolerance, motion, &work, &t, 0.0,
                     bed ? &memory->back_slope : nullptr, bed ? &memory->back_root : nullptr)) {
        if (bed) memory->back_root = t;
        if (t < 0.0) part += t * wall;
      }
    }
    // A balance on a bed with a closed-form stiffness starts the next tick's Newton steps.
    if (Eigen::Matrix2d unused; bed && law_.RadialJacobian(work.contact, &unused)) {
      memory->bed_part = part;
    }
    return part;
  };
  // The balance across the axis at the device's depth serves every depth tried along it: the
  // part goes no deeper than the device, and where the bore narrows ahead that balance already
  // has it clear of the narrowing (a balance taken at the part's own depth would run it into
  // the step and hold it there as if it were jammed).
  Eigen::Vector2d at = across(held_depth, &run->at_device);
  // Along the axis: where the law's resistance (stick-slip junctions, probed from the run's state
  // without advancing it) balances the spring k (held - y), the part at that balance across. The
  // resistance falls monotonically as the part goes deeper (a junction's spring, then the
  // kinetic level, against the way in), so the root between the part's last depth and the
  // device's is unique.
  auto axial = [&](double depth) {
    work.pose.depth = depth;
    work.pose.offset = at;
    motion.depth = depth;
    analyzer_.Evaluate(work.pose, &work.contact);
    ++work.contact_evaluations;
    LawState probe = run->law;
    if (!work.contact.engaged) probe = LawState{};
    work.wrench.SetZero();
    law_.Evaluate(work.contact, motion, &probe, &work.wrench);
    return k * (held_depth - depth) + work.wrench.force.y();
  };
  double depth = held_depth;
  bool lags = false;
  const double at_device = axial(held_depth);
  constexpr double kAxialTolerance = 1e-4;  // N, as across
  if (std::abs(at_device) > kAxialTolerance) {
    double lo = run->part_depth, hi = held_depth;
    double g_lo = axial(lo), g_hi = at_device;
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
      if (!run->lagged) run->at_part.line_slope = run->at_device.line_slope;
      at = across(depth, &run->at_part);
    }
  }
  run->lagged = lags;
  run->part = at;
  run->part_depth = depth;
  out->pose.offset = at;
  out->pose.depth = depth;
  motion.depth = depth;
  // The last probe's contact where it was taken at the part's pose (the same numbers).
  out->contact_evaluations = work.contact_evaluations;
  if (work.pose.offset == at && work.pose.depth == depth && work.pose.angle == out->pose.angle) {
    out->contact = work.contact;
  } else {
    analyzer_.Evaluate(out->pose, &out->contact);
    ++out->contact_evaluations;
  }
  // Out of engagement (withdrawn) the junctions let go, as in the rigid case.
  if (!out->contact.engaged) run->law = LawState{};
  out->wrench.SetZero();
  law_.Evaluate(out->contact, motion, &run->law, &out->wrench);
  out->elastic = law_.CheckElasticLimit(out->contact);
  // The device feels the spring that pulls the part towards it; the part sits where the
  // contact balances it, so the two agree to within the solves' tolerances.
  out->wrench.force.x() = k * (at.x() - held.x());
  out->wrench.force.y() = k * (depth - held_depth);
  out->wrench.force.z() = k * (at.y() - held.y());
  out->stiffness = (at == held && depth == held_depth) ? 0.0 : k;
  out->next = depth < 0.0 ? StageId::kPositioning : StageId::kConstrained;
  SetGap(out);
}

double ConstrainedStage::RadialStiffness(const MatingPose& pose, const MatingMotion& motion,
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
