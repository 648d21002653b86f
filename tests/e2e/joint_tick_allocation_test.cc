// The joint stage's tick (framework/runtime/joint_stage.h) must not allocate: the shipped scenes
// that join two features, under their robot and under the simulated hand, ticked through the
// scheduler with its safety chain and record while every operator new is counted.
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>

// Framework headers first: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include "framework/plugin/registry.h"
#include "framework/runtime/joint_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scene_stages.h"
#include "framework/runtime/scheduler.h"
#include "framework/runtime/screw_stage.h"
#include "framework/scenario/scene.h"
#include "framework/testing/allocation_counter.h"
#include "framework/testing/build_tree_plugins.h"
#include "framework/testing/cli_runner.h"
#include "framework/testing/hand_scene.h"

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

// The shipped scenario, or with the hand 1 mm off the axis as its device (written beside the
// test's outputs).
Scene JointScene(const std::string& file, bool hand) {
  const fs::path shipped = fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / file;
  if (!hand) return LoadScene(shipped, test_support::BuildTreePlugins());
  const fs::path written = test_support::EmptyFolder("joint-tick-allocation", file) / file;
  std::ofstream(written) << test_support::WithHand(test_support::ReadText(shipped), 1e-3,
                                                   test_support::kHandPushIn, 3.5);
  return LoadScene(written, test_support::BuildTreePlugins());
}

// The scene ticked through the scheduler (safety chain and record included) for its planned
// ticks while every operator new is counted, its constrained stage a `StageType`; `check` then
// reads what the run did.
template <class StageType>
void TickCountingAllocations(Scene scene, const std::function<void(const Scheduler&)>& check) {
  const PreparedScene prepared = Prepare(scene);
  SchedulerSettings settings = SceneSchedulerSettings(scene);
  settings.clock = ClockMode::kVirtual;
  settings.record = true;
  scene.device->Start(1.0 / settings.rate);
  const SceneStages stages = MakeSceneStages(scene, prepared, scene.device->spec());
  ASSERT_NE(dynamic_cast<const StageType*>(stages.constrained.get()), nullptr);
  settings.safety = RuntimeSafetySettings(scene.safety, scene.device->spec());
  Scheduler scheduler(*scene.device, *stages.positioning, *stages.constrained, settings);
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  std::uint64_t ticks = 0;
  while (ticks < scheduler.planned_ticks() &&
         scheduler.Tick(static_cast<double>(ticks) / settings.rate)) {
    ++ticks;
  }
  allocations.Stop();
  scene.device->Stop();
  EXPECT_EQ(allocations.count(), 0);
  check(scheduler);
}

TEST(JointTickAllocation, TheShippedJointsTickWithoutAllocating) {
  for (const char* file : {"keyed-hub.yaml", "two-pin-location.yaml"}) {
    for (const bool hand : {false, true}) {
      SCOPED_TRACE(std::string(file) + (hand ? ", the hand" : ", the robot"));
      TickCountingAllocations<JointStage>(JointScene(file, hand), [](const Scheduler& scheduler) {
        // The joint did its work: most of the run in contact, and ticks that differenced its
        // features, searched along kinks and reached the iteration limit.
        int constrained = 0;
        for (const TickRecord& record : scheduler.trace()) {
          constrained += record.stage == StageId::kConstrained ? 1 : 0;
        }
        EXPECT_GT(constrained, static_cast<int>(scheduler.trace().size()) / 2);
        EXPECT_GE(scheduler.StatsSoFar().contact_evaluations.max, 40.0);
      });
    }
  }
}

// The screw stage's tick (framework/runtime/screw_stage.h) neither: the shipped thread scenes, the
// wrench's run-down and tightening, the crooked start that jams and the hand's run-down.
TEST(ScrewTickAllocation, TheShippedThreadsTickWithoutAllocating) {
  for (const char* file : {"bolt-m10.yaml", "cross-thread.yaml", "nut-by-hand.yaml"}) {
    SCOPED_TRACE(file);
    TickCountingAllocations<ScrewStage>(JointScene(file, false), [](const Scheduler& scheduler) {
      // The screw did its work: the nut met the face or jammed.
      const ScrewOutput& last = scheduler.trace().back().screw;
      EXPECT_TRUE(last.seated || last.stopped);
    });
  }
}

}  // namespace
}  // namespace fitfeel
