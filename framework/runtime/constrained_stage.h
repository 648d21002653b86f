#pragma once

#include <limits>

#include "framework/core/export.h"
#include "framework/runtime/stage.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"
#include "framework/runtime/contact_search.h"
#include "framework/runtime/god_object.h"
#include "framework/runtime/quasi_static_settle.h"

namespace fitfeel {

// Mating under constraint (paper section 3): the device pose becomes a MatingPose in the fixed
// part's mating frame (see positioning_stage.h for the frame convention), the contact analyzer
// answers from its prepared tables and the law turns the contact state into the wrench on the
// moving part. Withdrawing the part past the entrance (depth < 0) hands back to positioning.
// Where the part is across the axis is one of three placements: held at the device's pose (a
// robot), settled under a load (QuasiStaticSettle), or a god object coupled to the device by a
// spring (GodObject). Evaluate allocates nothing: the collaborators are prepared and only read;
// what a placement carries between ticks lives in the run's state. Not copyable: the placements
// refer to the stage's own search.
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
  ConstrainedStage(const ConstrainedStage&) = delete;
  ConstrainedStage& operator=(const ConstrainedStage&) = delete;
  const Options& options() const { return options_; }

  StageId DoId() const override { return StageId::kConstrained; }

 protected:
  std::unique_ptr<StageState> DoMakeState() const override;
  void DoEvaluate(const PartState& part, StageState* state,
                  StageOutput* out) const noexcept override;

 private:
  // DoEvaluate in the analyzer's frame (Options::moving): `device` and the hand-over pose in
  // `out` already reflected where the outer part moves, the outputs left in that frame.
  void EvaluateInAnalyzerFrame(const PartState& part, StageState* state,
                               StageOutput* out) const noexcept;

  Options options_;
  // The analyzer and law with the probes and searches the two placements share, then the
  // placements (both refer to it).
  ContactSearch search_;
  QuasiStaticSettle settle_;
  GodObject god_object_;  // used only where options_.proxy_stiffness is finite
};

}  // namespace fitfeel
