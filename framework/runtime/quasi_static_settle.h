#pragma once

#include <limits>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/runtime/contact_search.h"

namespace fitfeel {

// What a settle carries from one tick to the next (in the run's state): where it left the
// part, and the slope of its last root along the load, from which the next tick's first probe
// is a Newton step (exact on a linear spring, the laws' radial force).
struct SettleMemory {
  Eigen::Vector2d offset{0.0, 0.0};
  double along_slope = 0.0;  // d(residual)/ds, N/m; 0 = not known yet
  // The contact's 2x2 stiffness (-dF/d(offset), N/m) of the last two-dimensional step; zero =
  // not known yet. The settle leaves the next tick's start one Newton step on it from where it
  // left the part, so that the sideways push a rotating or advancing contact builds up tick by
  // tick is taken off as it grows, not in a burst once it passes the tolerance.
  Eigen::Matrix2d stiffness = Eigen::Matrix2d::Zero();
  bool interference = false;  // the last settle ended with the parts interfering
  // The balance is a path over depth (a taper's part rides up as the bore narrows, an
  // interference fit's axis follows the parts' form): where the last root lay and at which
  // depth, and the path's slope d(root)/d(depth) between the last two roots with the depth
  // change between them. Where the last two slopes agree (a smooth path, not a clearance fit's
  // jump from one corner of the assembly space to the next at a table step), the next tick
  // starts extrapolated along it by its own advance.
  double depth = std::numeric_limits<double>::quiet_NaN();
  double depth_change = 0.0;
  Eigen::Vector2d root{0.0, 0.0};
  Eigen::Vector2d path{0.0, 0.0};
  bool smooth = false;
};

// The constrained stage's quasi-static placement: the part floats across the axis under a load
// (its weight, as the paper's robot lets it act) and rests where the contact carries it. Reads the
// prepared analyzer and law only; what it carries between ticks is the run's SettleMemory.
class FITFEEL_API QuasiStaticSettle {
 public:
  // `search` must outlive the settle.
  explicit QuasiStaticSettle(const ContactSearch& search) : search_(search) {}

  // Newton steps of a settle's two-dimensional balance before it falls back to sweeps along and
  // across the load (each step three contact evaluations, plus a slide along a flat wall; one
  // where the parts interfere, the stiffness then corrected by the step's secant).
  static constexpr int kNewtonSteps = 6;

  // Quasi-static placement (PartState::settle_load): finds the offset along the load where the
  // rendered radial force balances it, starting from and updating `*memory` (the previous
  // settled offset and slope), and leaves pose, contact and wrench there, the wrench from the
  // law with the run's `*law_state` (advanced once, at the settled pose). Returns false (outputs,
  // state and `*memory` untouched but for the evaluations counted) where nothing can carry the
  // load, e.g. before the surfaces overlap.
  bool Settle(const Eigen::Vector2d& load, const MatingMotion& motion, SettleMemory* memory,
              LawState* law_state, StageOutput* out) const noexcept;

 private:
  const ContactSearch& search_;
};

}  // namespace fitfeel
