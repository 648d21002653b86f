#pragma once

// A scene's run in virtual time on a prepared scene, set up as `fitfeel run` sets it up (the
// scene's scheduler settings, the device started at the run's rate, the two stages, the safety
// chain), for tests and benchmarks that run or step the scheduler themselves.

#include <optional>

#include "framework/runtime/prepare.h"
#include "framework/runtime/scene_stages.h"
#include "framework/runtime/scheduler.h"
#include "framework/scenario/scene.h"

namespace fitfeel::test_support {

// Starts the scene's device on construction and stops it on destruction; `scene` and `prepared`
// are borrowed and must outlive it.
class VirtualSceneRun {
 public:
  VirtualSceneRun(Scene& scene, const PreparedScene& prepared)
      : scene_(scene), settings_(SceneSchedulerSettings(scene)) {
    settings_.clock = ClockMode::kVirtual;
    // Started first: a device knows its limits (the hand's 2 b / T) only at its rate.
    scene.device->Start(1.0 / settings_.rate);
    stages_ = MakeSceneStages(scene, prepared, scene.device->spec());
    settings_.safety = RuntimeSafetySettings(scene.safety, scene.device->spec());
    scheduler_.emplace(*scene.device, *stages_.positioning, *stages_.constrained, settings_);
  }
  ~VirtualSceneRun() { scene_.device->Stop(); }
  VirtualSceneRun(const VirtualSceneRun&) = delete;
  VirtualSceneRun& operator=(const VirtualSceneRun&) = delete;

  Scheduler& scheduler() { return *scheduler_; }
  double rate() const { return settings_.rate; }

 private:
  Scene& scene_;
  SchedulerSettings settings_;
  SceneStages stages_;
  std::optional<Scheduler> scheduler_;
};

}  // namespace fitfeel::test_support
