#pragma once

#include <limits>

#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/gps_spec.h"
#include "framework/model/resistance_law.h"
#include "framework/runtime/stage.h"
#include "framework/scenario/part_motion_settings.h"

namespace fitfeel {

// Mating of a screw thread (docs/threads.md): the moving part's turn about the axis is the driver
// (a scripted wrench at its speed until its target, or the device's twist where a hand turns it),
// and its advance along the axis settles each tick where the contact's axial force balances the
// scene's axial load (a robot) or the hand's coupling spring: within the flanks' play the part
// runs free, on a flank it follows the lead, against the bearing face it builds preload. The
// part stays on the axis (the thread centres it). Per tick: no allocation, at most
// kMaxEvaluations contact evaluations.
class FITFEEL_API ScrewStage final : public Stage {
 public:
  struct Options {
    double depth_origin = 0.0;  // scene-frame y of depth 0
    Role moving = Role::kInner;
    // The hand's coupling spring along the axis (N/m); infinite: a robot, whose part takes the
    // scene's axial load.
    double proxy_stiffness = std::numeric_limits<double>::infinity();
    double axial_load = 0.0;  // N along +y, a robot's
    double lead = 0.0;        // the screw's advance per turn, m (> 0)
    // A robot's hold of the part tilted (MatingPose::tilt), added to the device's, rad.
    Eigen::Vector2d tilt{0.0, 0.0};
    // Without a wrench: the torsional spring between the device's twist and the part's (a hand
    // holding a nut at a lever arm, N*m/rad); infinite: the part takes the device's twist.
    double twist_stiffness = std::numeric_limits<double>::infinity();
    ScrewTurn turn;
  };
  static constexpr int kMaxEvaluations = 12;

  // `analyzer` and `law` prepared, outliving the stage. Throws UserError for an unprepared
  // analyzer or bad options.
  ScrewStage(const ContactAnalyzer& analyzer, const ResistanceLaw& law, const Options& options);
  const Options& options() const { return options_; }

 protected:
  StageId DoId() const override { return StageId::kConstrained; }
  std::unique_ptr<StageState> DoMakeState() const override;
  void DoEvaluate(const PartState& part, StageState* state,
                  StageOutput* out) const noexcept override;

 private:
  struct RunState;
  // The axial force on the part (analyzer frame) at `depth` and `angle`, the friction taken from
  // a copy of `law`'s state; counts the evaluation.
  double AxialForce(double depth, double angle, const Eigen::Vector2d& tilt, const LawState& law,
                    StageOutput* out) const noexcept;
  // Where the axial force and the load (plus the hand's spring towards `device_depth`) balance
  // at run->angle, starting from the last tick's depth carried by its last advance per turn over
  // the turn from `previous_angle`. out->contact is left at the depth returned.
  double SettleDepth(double previous_angle, double device_depth, RunState* run,
                     StageOutput* out) const noexcept;

  const ContactAnalyzer& analyzer_;
  const ResistanceLaw& law_;
  Options options_;
};

}  // namespace fitfeel
