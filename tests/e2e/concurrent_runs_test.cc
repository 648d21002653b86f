// Two runs of one prepared scene at once: the stages, analyzer, law and collider are shared and
// only read, each run has its own device, scheduler and state (docs/run-state.md). Whatever runs
// beside it, a run's trace is the one it gives alone. Built under ThreadSanitizer too (the `tsan`
// preset), where the same test is the data-race check.
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "framework/plugin/registry.h"
#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/outputs.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scheduler.h"
#include "framework/scenario/scene.h"
#include "framework/testing/build_tree_plugins.h"
#include "framework/testing/source_tree.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

using test_support::ShippedScenario;

namespace fs = std::filesystem;

// Strikes the fixed part's face off the axis (the positioning stage's FCL contact), backs off,
// centres and inserts at the case study's 10 mm/s carrying 2 N across the axis: every stage and
// the settling solve are exercised. Position-controlled: the path does not depend on the force.
class StrikeThenInsertDevice final : public Device {
 public:
  DeviceSpec DoSpec() const override {
    DeviceSpec s;
    s.model = "strike-then-insert path";
    s.max_force = s.max_continuous_force = s.max_stiffness = HUGE_VAL;
    s.workspace = Eigen::Vector3d::Constant(1.0);
    return s;
  }

 protected:
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double time, DeviceState* out) noexcept override {
    out->time = time;
    Eigen::Vector3d p;
    if (time < 0.3) {  // 3 mm off the axis: the shaft's end meets the bushing's face at 0.25 s
      p = Eigen::Vector3d(3e-3, -1e-3 + 4e-3 * time, 0.0);
    } else if (time < 0.4) {  // back off and centre
      p = Eigen::Vector3d(3e-3 * (0.4 - time) / 0.1, -0.5e-3, 0.0);
    } else {
      p = Eigen::Vector3d(0.0, -0.5e-3 + 10e-3 * (time - 0.4), 0.0);
    }
    out->velocity = (p - out->position) / 1e-3;
    out->position = p;
  }
  void DoWrite(const Wrench& wrench) noexcept override { delivered_ = wrench; }

 private:
  Wrench delivered_;
};

struct SharedScene {
  PreparedScene prepared;
  std::unique_ptr<PositioningStage> positioning;
  std::unique_ptr<ConstrainedStage> constrained;
  SchedulerSettings settings;
};

// The stages as `fitfeel run` builds them (run.cc), once.
SharedScene PrepareShared(const Scene& scene) {
  SharedScene shared;
  shared.prepared = Prepare(scene);
  PositioningStage::Options free_motion;
  free_motion.free_stiffness =
      FreeMotionStiffness(scene.model.contact_stiffness, scene.device->spec().max_stiffness);
  shared.positioning = std::make_unique<PositioningStage>(
      free_motion, shared.prepared.surface->MakeCoarseMeshes(scene.inner, scene.outer),
      scene.moving);
  shared.constrained =
      std::make_unique<ConstrainedStage>(*shared.prepared.analyzer, *shared.prepared.law);
  shared.settings = SceneSchedulerSettings(scene);
  shared.settings.clock = ClockMode::kVirtual;
  shared.settings.safety = RuntimeSafetySettings(scene.safety, scene.device->spec());
  return shared;
}

// One run on a device of its own; the trace without the measured compute time.
std::vector<std::string> RunOn(Device& device, const SharedScene& shared) {
  device.Start(1.0 / shared.settings.rate);
  Scheduler scheduler(device, *shared.positioning, *shared.constrained, shared.settings);
  scheduler.Run();
  device.Stop();
  std::vector<std::string> rows;
  for (TickRecord r : scheduler.trace()) {
    r.compute_us = 0.0;
    rows.push_back(TraceRow(r));
  }
  return rows;
}

// Runs on `first` and `second` one after the other, then both at once on two threads.
void ExpectSameTracesConcurrently(Device& first, Device& second, const SharedScene& shared,
                                  const std::string& what) {
  const std::vector<std::string> alone_first = RunOn(first, shared);
  const std::vector<std::string> alone_second = RunOn(second, shared);
  ASSERT_EQ(alone_first, alone_second) << what << ": the two devices differ";
  std::vector<std::string> together_first, together_second;
  std::thread other([&] { together_second = RunOn(second, shared); });
  together_first = RunOn(first, shared);
  other.join();
  ASSERT_EQ(together_first.size(), alone_first.size()) << what;
  ASSERT_EQ(together_second.size(), alone_first.size()) << what;
  for (std::size_t k = 0; k < alone_first.size(); ++k) {
    ASSERT_EQ(together_first[k], alone_first[k]) << what << ", tick " << k;
    ASSERT_EQ(together_second[k], alone_first[k]) << what << ", tick " << k;
  }
}

class ConcurrentRunsTest : public ::testing::TestWithParam<std::string> {};

// Every shipped scenario: each surface plugin's analyzer and law, settled and dynamic devices.
TEST_P(ConcurrentRunsTest, TwoRunsOfOnePreparedSceneMatchTheRunsAlone) {
  // Loaded twice: the same configuration on two device instances (a device is one run's I/O).
  const Scene scene = LoadScene(ShippedScenario(GetParam()), test_support::BuildTreePlugins());
  const Scene twin = LoadScene(ShippedScenario(GetParam()), test_support::BuildTreePlugins());
  const SharedScene shared = PrepareShared(scene);
  ExpectSameTracesConcurrently(*scene.device, *twin.device, shared, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Shipped, ConcurrentRunsTest,
                         ::testing::Values("paper-case1-h7js6.yaml", "paper-case1-h7g6.yaml",
                                           "paper-case1-ve1.yaml", "pin-cylindrical.yaml",
                                           "taper-pin.yaml", "key-parallel.yaml",
                                           "square-shaft.yaml", "knuckle-bearing.yaml"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = param.param.substr(0, param.param.find('.'));
                           for (char& c : name)
                             c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

TEST(ConcurrentRunsTest, FreeMotionCollisionsShareOneCollider) {
  const Scene scene =
      LoadScene(ShippedScenario("paper-case1-h7js6.yaml"), test_support::BuildTreePlugins());
  const SharedScene shared = PrepareShared(scene);
  ASSERT_TRUE(shared.positioning->collides());
  StrikeThenInsertDevice first, second;
  // The path does strike the face: some positioning tick renders a force.
  first.Start(1e-3);
  Scheduler probe(first, *shared.positioning, *shared.constrained, shared.settings);
  probe.Run();
  bool struck = false, inserted = false;
  for (const TickRecord& r : probe.trace()) {
    struck = struck || (r.stage == StageId::kPositioning && r.wrench.force.y() < 0.0);
    inserted = inserted || (r.stage == StageId::kConstrained && r.pose.depth > 1e-3);
  }
  ASSERT_TRUE(struck);
  ASSERT_TRUE(inserted);
  ExpectSameTracesConcurrently(first, second, shared, "strike then insert");
}

}  // namespace
}  // namespace fitfeel
