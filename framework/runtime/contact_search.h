#pragma once

#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"
#include "framework/runtime/stage.h"

namespace fitfeel {

// The finest travel the 1-D searches resolve (IllinoisRoot's brackets end there). Where a
// tolerance in force is finer than what a picometre of travel makes on the last root's slope, a
// search stops at that force instead: it could only probe within the picometre.
inline constexpr double kPicometre = 1e-12;

// The constrained stage's probes of the contact across the axis at one depth: the analyzer and
// the law evaluated with the part at an offset, and the one-dimensional searches along a line of
// offsets that the quasi-static settle and the god object build their balances from. Reads the
// prepared analyzer and law only; a search's scratch is the caller's `work` output, so one
// ContactSearch serves any number of runs.
class FITFEEL_API ContactSearch {
 public:
  // Both must be prepared and outlive the search.
  ContactSearch(const ContactAnalyzer& analyzer, const ResistanceLaw& law)
      : analyzer_(analyzer), law_(law) {}

  const ContactAnalyzer& analyzer() const { return analyzer_; }
  const ResistanceLaw& law() const { return law_; }

  // Finds s with the contact's push-back along -axis equal to `target` (within `tolerance`, N)
  // at origin + s * axis, evaluating into `work`; false if no such point lies within reach.
  // With `spring` > 0 the target falls as the part moves: target - spring * s (the coupling
  // spring of a god object whose device lies at s = target / spring). `slope`, when given, is
  // the residual's slope at the last root (N/m; 0 = unknown): the search's first probe is a
  // Newton step from it, and it learns the slope of this root. `hint`, when given and finite, is
  // where the root lay last time (s from this origin): the search first brackets the root in a
  // few nanometres around it (a root at the foot of a convex wall, where neither a slope nor a
  // bracket from the origin helps: the texture's smooth onset of contact).
  bool SolveAlong(const Eigen::Vector2d& origin, const Eigen::Vector2d& axis, double target,
                  double tolerance, const MatingMotion& motion, StageOutput* work, double* solution,
                  double spring = 0.0, double* slope = nullptr,
                  const double* hint = nullptr) const noexcept;
  // The contact and the law's wrench (without history) with the part at `offset`, left in
  // `work`; returns the radial force (x, z).
  Eigen::Vector2d ProbeAt(const Eigen::Vector2d& offset, const MatingMotion& motion,
                          StageOutput* work) const noexcept;
  // The same, answered from `work` where its last probe was taken at `offset`. The searches keep
  // `work` holding the contact and the law's push (without history) at work->pose, or a pose
  // that no offset equals (NaN) after evaluating anything else into it (the god object's axial
  // balance, whose push has the run's history, is followed by a new anchor before any search).
  Eigen::Vector2d ForceAt(const Eigen::Vector2d& offset, const MatingMotion& motion,
                          StageOutput* work) const noexcept;
  // -dF/dx of the radial force along its own direction, by a second evaluation 1 nm deeper
  // (exact for the piecewise-linear laws of eqs. 9-12 away from a kink); 0 without contact.
  // Counts its evaluation in `*evaluations`.
  double RadialStiffness(const MatingPose& pose, const MatingMotion& motion, const Wrench& wrench,
                         int* evaluations) const noexcept;

 private:
  const ContactAnalyzer& analyzer_;
  const ResistanceLaw& law_;
};

// The free way outwards (StageOutput::gap) from the output's contact and stiffness.
FITFEEL_API void SetGap(StageOutput* out) noexcept;

}  // namespace fitfeel
