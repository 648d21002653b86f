#pragma once

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
  // Both must be prepared and outlive the stage. Throws UserError if the analyzer is not prepared.
  // Probes (settling searches, stiffness) evaluate the law without history; the tick's wrench
  // comes from one evaluation with the run's law state at the pose the part is rendered at.
  ConstrainedStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law);

  StageId id() const override { return StageId::kConstrained; }

 protected:
  std::unique_ptr<StageState> DoMakeState() const override;
  void DoEvaluate(const DeviceState& device, StageState* state,
                  StageOutput* out) const noexcept override;

 private:
  // -dF/dx of the radial force along its own direction, by a second evaluation 1 nm deeper
  // (exact for the piecewise-linear laws of eqs. 9-12 away from a kink); 0 without contact.
  double RadialStiffness(const MatingPose& pose, const MatingMotion& motion,
                         const Wrench& wrench) const noexcept;

  // Quasi-static placement (DeviceState::settle_load): finds the offset along the load where the
  // rendered radial force balances it, starting from and updating `*last_settled` (the previous
  // settled offset), and leaves pose, contact and wrench there, the wrench from the law with the
  // run's `*law_state` (advanced once, at the settled pose). Returns false (outputs, state and
  // `*last_settled` untouched) where nothing can carry the load, e.g. before the surfaces overlap.
  bool Settle(const Eigen::Vector2d& load, const MatingMotion& motion,
              Eigen::Vector2d* last_settled, LawState* law_state,
              StageOutput* out) const noexcept;
  // Finds s with the contact's push-back along -axis equal to `target` (within `tolerance`, N)
  // at origin + s * axis, evaluating into `work`; false if no such point lies within reach.
  bool SolveAlong(const Eigen::Vector2d& origin, const Eigen::Vector2d& axis, double target,
                  double tolerance, const MatingMotion& motion, StageOutput* work,
                  double* solution) const noexcept;

  const ContactAnalyzer& analyzer_;
  const ResistanceLaw& law_;
};

}  // namespace fitfeel
