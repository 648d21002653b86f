#pragma once

#include <array>
#include <limits>
#include <memory>
#include <string_view>

#include "framework/core/export.h"
#include "framework/core/wrench.h"
#include "framework/model/contact_analyzer.h"
#include "framework/model/joint_features.h"
#include "framework/model/resistance_law.h"
#include "framework/runtime/part_state.h"

namespace fitfeel {

// Identifies the stage of an assembly (paper section 3): free positioning, then constrained mating.
enum class StageId : int { kPositioning = 0, kConstrained = 1 };

FITFEEL_API std::string_view ToString(StageId stage);

// What a screw's stage adds to its output (ScrewStage): the joint's state this tick.
struct ScrewOutput {
  bool active = false;         // written by a screw stage
  double preload = 0.0;        // the bearing face's clamp force, N
  double torque = 0.0;         // the torque turning the part against the contact, N*m
  double thread_torque = 0.0;  // of it, against the flanks
  double head_torque = 0.0;    // and against the bearing face
  bool seated = false;         // the bearing face has met
  double snug_angle = 0.0;     // the part's angle when it met, rad
  bool stopped = false;        // the wrench reached its target and holds
};

// Output of one stage tick.
struct StageOutput {
  Wrench wrench;                         // on the moving part, scene frame
  MatingPose pose;                       // where the moving part is relative to the fixed one
  ContactState contact;                  // filled by the constrained stage
  ElasticLimitCheck elastic;             // the contact's stresses against yield (constrained)
  StageId next = StageId::kPositioning;  // stage for the next tick (hand-over)
  // Radial stiffness of the contact at this pose, -dF/dx along the force (N/m); 0 when free. A
  // dynamic moving part (PartMotion) and a device with inertia of its own (the scripted hand)
  // integrate it implicitly, the safety chain's coupling too.
  double stiffness = 0.0;
  // Free space in front of the part when it is not in contact: the distance (m) it can move along
  // `gap_direction` (unit, in the (x, z) cross-section) before touching; infinity when unknown.
  double gap = std::numeric_limits<double>::infinity();
  Eigen::Vector2d gap_direction{0.0, 0.0};
  // The stage that wrote this output (set by Stage::Evaluate). The run keeps one output, so on
  // entry a stage reads the previous tick's: another stage's means a hand-over, whose pose is
  // where the part was, and the moving part continues from there.
  StageId stage = StageId::kPositioning;
  // The contact analyzer's evaluations this tick (Stage::Evaluate counts from 0): the tick's
  // cost in its own unit, the same on every machine, where its time is the machine's.
  int contact_evaluations = 0;
  // A joint of several features (JointStage): each feature's axial force on the moving part
  // (scene y, N), in the scene's order; the rest of the output sums them. 0 features otherwise.
  int feature_count = 0;
  std::array<double, kMaxJointFeatures> feature_axial{};
  ScrewOutput screw;
};

class Stage;

// What one run of a stage changes from tick to tick (see docs/run-state.md): a stage itself is
// immutable once built, so one prepared stage serves any number of runs at once, each with its
// own state. A stage derives its own kind; the base carries only which stage made it.
class FITFEEL_API StageState {
 public:
  virtual ~StageState();
  StageState(const StageState&) = delete;
  StageState& operator=(const StageState&) = delete;
  const Stage* owner() const { return owner_; }

 protected:
  StageState() = default;

 private:
  friend class Stage;
  const Stage* owner_ = nullptr;
};

// One stage of the assembly. Construction and MakeState may allocate; Evaluate is the per-tick
// path and reads the stage, writing only the run's state and the output.
class FITFEEL_API Stage {
 public:
  virtual ~Stage();
  StageId id() const { return DoId(); }
  // A fresh state for one run (prepare time: may allocate). Never null.
  std::unique_ptr<StageState> MakeState() const;
  // Per tick. `state` must come from this stage's MakeState (aborts otherwise) and serve one
  // thread at a time; different states may be evaluated concurrently.
  void Evaluate(const PartState& part, StageState* state, StageOutput* out) const noexcept;

 protected:
  virtual StageId DoId() const = 0;
  // The default is a state with nothing in it, for stages that keep nothing between ticks.
  virtual std::unique_ptr<StageState> DoMakeState() const;
  virtual void DoEvaluate(const PartState& part, StageState* state,
                          StageOutput* out) const noexcept = 0;
};

}  // namespace fitfeel
