#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/resistance_law.h"
#include "framework/scenario/scene.h"
#include "framework/view/frame_codec.h"
#include "framework/view/view_sample.h"

namespace fitfeel::view {

// What the viewer knows of a scene, built once before serving and read-only afterwards (so the
// server thread may use it while the tick runs): both parts' skin model shapes drawn as a run
// draws them (same scene, same seed, same shapes), their render meshes, and a contact analyzer and
// law of its own, so that pressure maps and assembly spaces are computed on the server's thread
// without touching the objects the tick uses.
class FITFEEL_API ViewModel {
 public:
  // Throws UserError/ScenarioError as a run would for a scene that cannot be prepared. A surface
  // type without a law (or without an analyzer) still gives a model: its parts are shown, without
  // pressure, and `status()` says why.
  ViewModel(const Scene& scene, std::uint64_t seed);
  ~ViewModel();
  ViewModel(const ViewModel&) = delete;
  ViewModel& operator=(const ViewModel&) = delete;

  // The scene message (JSON text) a client receives first.
  const std::string& scene_message() const { return scene_message_; }
  // The mesh frame of the inner (0) or outer (1) part.
  const std::string& mesh_frame(int part) const;
  bool renders_forces() const { return law_ != nullptr; }
  Role moving() const { return scene_.moving; }
  const std::string& status() const { return status_; }

  // Pressure map (quantised) and assembly space at the sample's pose (in the outer part's frame,
  // ViewSample), the analyzer's own. Not for the tick.
  StateExtras Extras(const ViewSample& sample) const;
  // Fills the sample's contact fields (engaged, interference, assembly extent, ...) from the
  // viewer's own analyzer at its pose: for rows of a finished run that recorded only the pose and
  // the forces.
  void FillContact(ViewSample* sample) const;

 private:
  Scene scene_;
  std::unique_ptr<SkinModelShape> inner_, outer_;
  std::unique_ptr<ContactAnalyzer> analyzer_;
  std::unique_ptr<ResistanceLaw> law_;
  double pressure_per_interference_ = 0.0;  // Pa/m; 0 when the law reports none
  std::string status_;
  std::string scene_message_;
  std::string mesh_frames_[2];
};

}  // namespace fitfeel::view
