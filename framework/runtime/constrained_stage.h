#pragma once

#include <limits>

#include "framework/core/export.h"
#include "framework/device/stage.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"

namespace fitfeel {

// Mating under constraint (paper section 3): the device pose becomes a MatingPose in the fixed
// part's mating frame (see positioning_stage.h for the frame convention), the contact analyzer
// answers from its prepared tables and the law turns the contact state into the wrench on the
// moving part. Withdrawing the part past the entrance (depth < 0) hands back to positioning.
// Evaluate allocates nothing: both collaborators are prepared and only read; where the last
// settled tick left the part (the next settle's starting point) lives in the run's state.
class FITFEEL_API ConstrainedStage final : public Stage {
 public:
  struct Options {
    // The scene-frame y of mating depth 0 (the positioning stage's depth_origin: a lead-in's
    // capture depth); the stage reports and evaluates depth = y - depth_origin and hands back
    // below 0.
    double depth_origin = 0.0;
    // The stiffness of the spring that couples the device to the moving part across the axis
    // (the positioning stage's k_free), N/m. Infinite: the device holds the part rigidly (a
    // robot), and the contact is evaluated where the device is. Finite: the part is a god object
    // across the axis, at the offset where the contact's push balances that spring pulling it
    // towards the device; the device feels the spring. Without it, a device that renders at
    // most k_free, held a little into the wall by the hand, would put the part micrometres into
    // a contact of kN/um.
    double proxy_stiffness = std::numeric_limits<double>::infinity();
    // The part the device moves (Scene::moving). The analyzer and the law describe the inner part
    // in the outer part's frame; with the outer part moving that is the scene frame reflected in
    // z (AnalyzerPose): the stage reflects the device's position, velocities and load on the way
    // in and its pose, wrench, gap and contact directions on the way out, so that what it
    // reports stays in the scene frame.
    Role moving = Role::kInner;
  };

  // Both must be prepared and outlive the stage. Throws UserError if the analyzer is not prepared.
  // Probes (settling searches, stiffness) evaluate the law without history; the tick's wrench
  // comes from one evaluation with the run's law state at the pose the part is rendered at.
  ConstrainedStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law);
  // Also throws UserError for a non-finite depth origin or a proxy stiffness that is not > 0.
  ConstrainedStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law,
                   const Options& options);
  const Options& options() const { return options_; }

  StageId id() const override { return StageId::kConstrained; }

  // Newton steps of a settle's two-dimensional balance before it falls back to sweeps along and
  // across the load (each step three contact evaluations, plus a slide along a flat wall; one
  // where the parts interfere, the stiffness then corrected by the step's secant).
  static constexpr int kSettleNewtonSteps = 6;

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

  // What the god object's balance across the axis at one depth carries from tick to tick.
  struct AcrossMemory {
    // On a Winkler bed (the cone's, the sphere's): the last balance's slope (the wall's
    // stiffness plus the spring's, N/m; 0 = not known yet) and where it lay from the device (m;
    // NaN = not known yet); the next tick's search starts around that root.
    double across_slope = 0.0;
    double across_root = std::numeric_limits<double>::quiet_NaN();
    // The same for the step back out of the wall along the push (where the push exceeds the
    // pull).
    double back_slope = 0.0;
    double back_root = std::numeric_limits<double>::quiet_NaN();
    // On a Winkler bed whose stiffness comes in closed form (ResistanceLaw::RadialJacobian):
    // where the last balance left the part (NaN = not known, or free), the next one's start.
    Eigen::Vector2d bed_part{std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::quiet_NaN()};
    // On an assembly space's edge: the slope of the last balance on the line from the edge to
    // the device (the wall's stiffness along it plus the spring's, N/m; 0 = not known yet).
    double line_slope = 0.0;
  };

 protected:
  std::unique_ptr<StageState> DoMakeState() const override;
  void DoEvaluate(const DeviceState& device, StageState* state,
                  StageOutput* out) const noexcept override;

 private:
  // DoEvaluate in the analyzer's frame (Options::moving): `device` and the hand-over pose in
  // `out` already reflected where the outer part moves, the outputs left in that frame.
  void EvaluateInAnalyzerFrame(const DeviceState& device, StageState* state,
                               StageOutput* out) const noexcept;
  // The free way outwards (StageOutput::gap) from the output's contact and stiffness.
  static void SetGap(StageOutput* out) noexcept;
  // -dF/dx of the radial force along its own direction, by a second evaluation 1 nm deeper
  // (exact for the piecewise-linear laws of eqs. 9-12 away from a kink); 0 without contact.
  // Counts its evaluation in `*evaluations`.
  double RadialStiffness(const MatingPose& pose, const MatingMotion& motion, const Wrench& wrench,
                         int* evaluations) const noexcept;

  // Quasi-static placement (DeviceState::load): finds the offset along the load where the
  // rendered radial force balances it, starting from and updating `*memory` (the previous
  // settled offset and slope), and leaves pose, contact and wrench there, the wrench from the
  // law with the run's `*law_state` (advanced once, at the settled pose). Returns false (outputs,
  // state and `*memory` untouched but for the evaluations counted) where nothing can carry the
  // load, e.g. before the surfaces overlap.
  bool Settle(const Eigen::Vector2d& load, const MatingMotion& motion, SettleMemory* memory,
              LawState* law_state, StageOutput* out) const noexcept;
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
  // The god object (Options::proxy_stiffness): moves the part from where it was (in `state`)
  // towards the device's pose (out->pose on entry) until the contact's push balances the
  // spring across the axis, and the law's resistance balances it along the axis; leaves the
  // outputs at the part's pose with the spring's wrench on the device.
  void FollowDevice(const MatingMotion& device_motion, StageState* state,
                    StageOutput* out) const noexcept;

  const ContactAnalyzer& analyzer_;
  const ResistanceLaw& law_;
  Options options_;
};

}  // namespace fitfeel
