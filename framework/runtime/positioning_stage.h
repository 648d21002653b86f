#pragma once

#include "framework/core/export.h"
#include "framework/device/stage.h"

namespace fitfeel {

// Frame convention of a run (shared by every stage and device): the scene frame is the fixed
// part's mating frame. y is the mating axis, pointing in the direction of insertion; the fixed
// part's entrance (its first cross-section met by the moving part) is at y = 0. A device reports
// the pose of the moving part's leading end on its axis, and the orientation whose y axis is the
// moving part's axis. The insertion depth is then the y of the leading end.

// Free motion before mating (paper section 3: "positioning stage"). Renders no resistance and
// hands over to the constrained stage once the leading end has reached the entrance (depth >= 0)
// with the part's axis aligned with the mating axis and inside the entrance's capture radius.
//
// Not done yet: collision of the parts' coarse meshes with FCL while they move freely (the
// architecture places FCL here and only here: mesh-mesh queries between mated surfaces cost
// 1-35 ms). Until it is written, free motion is collision-free: a part that misses the entrance
// passes through the fixed part's face without resistance.
class FITFEEL_API PositioningStage final : public Stage {
 public:
  struct Options {
    // Largest tilt of the moving axis against the mating axis accepted at the hand-over. The
    // constrained model (paper eqs. 9-12) describes a part whose axis is parallel to the mating
    // axis; 1 degree is what a lead chamfer lets through on a 20 mm fit without jamming in
    // practice, and the constrained stage then ignores the residual tilt.
    double alignment_tolerance = 0.017453292519943295;  // rad (1 degree)
    // Largest radial offset of the leading end from the mating axis accepted at the hand-over: a
    // 0.5 mm x 45 degree edge break (ISO 13715's common default) guides an axis that far off into
    // the bore.
    double capture_radius = 0.5e-3;  // m
  };

  PositioningStage();
  // Throws UserError for a negative or non-finite option.
  explicit PositioningStage(const Options& options);

  StageId id() const override { return StageId::kPositioning; }
  const Options& options() const { return options_; }

 protected:
  void DoEvaluate(const DeviceState& device, StageOutput* out) const noexcept override;

 private:
  Options options_;
  double cos_alignment_tolerance_ = 1.0;
};

// The moving part's pose in the fixed part's mating frame (see the convention above): depth = y
// of the leading end, offset = its (x, z), angle = the twist of the orientation about y.
FITFEEL_API MatingPose MatingPoseOf(const DeviceState& device) noexcept;

}  // namespace fitfeel
