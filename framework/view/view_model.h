#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"
#include "framework/runtime/prepare_worker.h"
#include "framework/scenario/scene.h"
#include "framework/view/frame_codec.h"
#include "framework/view/part_placement.h"
#include "framework/view/view_sample.h"

namespace fitfeel::view {

// What the viewer knows of a scene, built once before serving and read-only afterwards (so the
// server thread may use it while the tick runs): both parts' skin model shapes drawn as a run
// draws them (same scene, same seed, same shapes), their render meshes, and a contact analyzer and
// law of its own, so that pressure maps and assembly spaces are computed on the server's thread
// without touching the objects the tick uses.
//
// A several-feature scene: every feature's two parts, drawn (shapes, then position deviations)
// as Prepare draws them, their render meshes placed in the joint frame (PartPlacement), and the
// datum feature's analyzer and law for the pressure map and the assembly space.
class FITFEEL_API ViewModel {
 public:
  // Throws UserError/ScenarioError as a run would for a scene that cannot be prepared. A surface
  // type without a law (or without an analyzer) still gives a model: its parts are shown, without
  // pressure, and `status()` says why. `step`: the scene's index among a sequence's steps, which
  // its scene message names (`step`), or -1 for a scene of its own, whose message names none.
  // `progressive`: the analyzer is ready to touch when the constructor returns and prepares the
  // rest of its tables on a thread of its own (PrepareWorker); a pose past its frontier is
  // answered at the frontier until then. For a live scene whose page shows states as they come
  // (LiveSession); a finished run's rows are filled at once and need the whole tables.
  ViewModel(const Scene& scene, std::uint64_t seed, int step = -1, bool progressive = false);
  ~ViewModel();
  ViewModel(const ViewModel&) = delete;
  ViewModel& operator=(const ViewModel&) = delete;

  // The scene message (JSON text) a client receives first.
  const std::string& scene_message() const { return scene_message_; }
  // The same marked `companion`: true, for a comparison's other scene, drawn beside the one that
  // renders (ServedStep::companion).
  const std::string& companion_message() const { return companion_message_; }
  // The mesh frames a client receives after the scene message, in order: the inner (0) and the
  // outer (1) part of a one-feature scene; of a several-feature scene, each feature's inner part
  // and then its outer part (frame 2 i + side), feature by feature.
  int mesh_count() const { return static_cast<int>(mesh_frames_.size()); }
  const std::string& mesh_frame(int k) const;
  bool renders_forces() const { return law_ != nullptr; }
  Role moving() const { return scene_.moving; }
  bool several_features() const { return !scene_.features.empty(); }
  const std::string& status() const { return status_; }

  // Pressure map (quantised) and assembly space at the sample's pose (in the outer part's frame,
  // ViewSample), the analyzer's own. Not for the tick.
  StateExtras Extras(const ViewSample& sample) const;
  // Fills the sample's contact fields (engaged, interference, assembly extent, ...) from the
  // viewer's own analyzer at its pose: for rows of a finished run that recorded only the pose and
  // the forces.
  void FillContact(ViewSample* sample) const;

  // A several-feature scene: each feature's position deviations as drawn (inner side, outer side;
  // joint frame, m) and where each part is drawn (feature i's inner part at 2 i, its outer part at
  // 2 i + 1). Empty for a one-feature scene.
  const std::vector<std::array<Eigen::Vector2d, 2>>& position_deviations() const {
    return position_deviations_;
  }
  const std::vector<PartPlacement>& placements() const { return placements_; }

 private:
  // The pose the datum feature's analyzer takes for a sample: the sample's own in a one-feature
  // scene; in a several-feature scene the datum feature's pose in its own frame (turned by its
  // `angle`), as the JointStage gives it.
  MatingPose DatumPose(const ViewSample& sample) const;

  Scene scene_;
  std::unique_ptr<SkinModelShape> inner_, outer_;
  std::unique_ptr<ContactAnalyzer> analyzer_;
  std::unique_ptr<ResistanceLaw> law_;
  double pressure_per_interference_ = 0.0;  // Pa/m; 0 when the law reports none
  std::string status_;
  std::string scene_message_;
  std::string companion_message_;
  std::vector<std::string> mesh_frames_;
  std::vector<std::array<Eigen::Vector2d, 2>> position_deviations_;
  std::vector<PartPlacement> placements_;
  // Last, so that it is stopped first: it prepares analyzer_'s tables.
  std::unique_ptr<PrepareWorker> rest_;
};

}  // namespace fitfeel::view
