// Progressive prepare in whole runs of shipped cylindrical scenes: a run whose rest is
// prepared after the ready steps traces the same bits as one prepared whole; a device that outruns
// a stalled worker feels the frontier's state held, counted in the summary; a run interrupted
// while its worker waits stops it.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "framework/core/interrupt.h"
#include "framework/runtime/outputs.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/run.h"
#include "framework/runtime/trace_columns.h"
#include "framework/scenario/scene.h"
#include "framework/testing/build_tree_plugins.h"
#include "framework/testing/source_tree.h"
#include "framework/testing/stop_at_tick.h"
#include "framework/testing/virtual_scene_run.h"

// After the project headers: <signal.h> (via gtest) defines a macro named si_value.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

using test_support::BuildTreePlugins;
using test_support::ShippedScenario;
using test_support::StopAtTick;

Scene LoadShipped(const std::string& name) {
  return LoadScene(ShippedScenario(name + ".yaml"), BuildTreePlugins());
}

// Every tick of `scene` in virtual time on `prepared`, as `fitfeel run` ticks it.
std::vector<TickRecord> RunTicks(Scene& scene, const PreparedScene& prepared) {
  test_support::VirtualSceneRun run(scene, prepared);
  run.scheduler().Run();
  return run.scheduler().trace();
}

// trace.csv's numbers of each tick but its compute time (a measurement), bit for bit.
void ExpectSameTrace(const std::vector<TickRecord>& a, const std::vector<TickRecord>& b,
                     const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  const int count = TraceColumnCount(0, false);
  const std::vector<TraceColumn> columns = TraceColumns({}, false);
  std::vector<double> x(static_cast<std::size_t>(count)), y(x.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    TraceValues(a[k], 0, false, x.data());
    TraceValues(b[k], 0, false, y.data());
    for (std::size_t c = 0; c < x.size(); ++c) {
      if (columns[c].name == "tick_us") continue;
      ASSERT_EQ(std::memcmp(&x[c], &y[c], sizeof(double)), 0)
          << what << ": tick " << k << " column " << columns[c].name << ": " << x[c] << " and "
          << y[c];
    }
  }
}

double Reach(const Scene& scene) { return scene.device->reach(scene.run.duration); }

// The press fit that prepares longest, a transition fit's elastic solves, and a clearance pin.
class ProgressiveRun : public ::testing::TestWithParam<std::string> {};

TEST_P(ProgressiveRun, TracesTheSameBitsAsAWholePrepare) {
  Scene whole_scene = LoadShipped(GetParam());
  const PreparedScene whole = Prepare(whole_scene, nullptr, Reach(whole_scene));
  const std::vector<TickRecord> reference = RunTicks(whole_scene, whole);

  // The rest finished at once before the first tick, as a run in virtual time does.
  Scene scene = LoadShipped(GetParam());
  ProgressiveSettings settings;
  settings.worker = false;
  PreparedScene prepared = PrepareProgressive(scene, settings, nullptr, Reach(scene));
  EXPECT_LE(prepared.ready_seconds, prepared.total_seconds);
  prepared.FinishPreparing();
  EXPECT_EQ(prepared.rest, nullptr);
  ExpectSameTrace(reference, RunTicks(scene, prepared), "finished at once");

  // Part of the rest on the worker thread, then finished here.
  Scene threaded_scene = LoadShipped(GetParam());
  settings.worker = true;
  PreparedScene threaded = PrepareProgressive(threaded_scene, settings, nullptr, Reach(scene));
  threaded.FinishPreparing();
  EXPECT_GE(threaded.total_seconds, threaded.ready_seconds);
  ExpectSameTrace(reference, RunTicks(threaded_scene, threaded), "worker, then finished");
}

INSTANTIATE_TEST_SUITE_P(Shipped, ProgressiveRun,
                         ::testing::Values("fits-20mm-h7n6", "paper-case1-h7js6",
                                           "pin-cylindrical"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = param.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(ProgressiveRunHeld, ADeviceThatOutrunsAStalledWorkerFeelsTheFrontierHeldAndCounted) {
  Scene scene = LoadShipped("fits-20mm-h7n6");
  std::atomic<bool> go{false};
  std::atomic<int> asked{0};
  ProgressiveSettings settings;
  settings.pace = [&] {
    asked.fetch_add(1);
    return go.load();
  };
  PreparedScene prepared = PrepareProgressive(scene, settings, nullptr, Reach(scene));
  const double frontier = prepared.analyzer->prepared_depth();
  ASSERT_LT(frontier, 0.005);  // the worker never moved it
  const std::vector<TickRecord> trace = RunTicks(scene, prepared);

  std::uint64_t held = 0, stretch = 0, longest = 0;
  double deepest = 0.0;
  const ContactState* first = nullptr;
  for (const TickRecord& r : trace) {
    if (!(r.contact.held_depth > 0.0)) {
      stretch = 0;
      continue;
    }
    ++held;
    longest = std::max(longest, ++stretch);
    deepest = std::max(deepest, r.contact.held_depth);
    // Every held tick feels the one state of the frontier: no jump while held.
    if (first == nullptr) first = &r.contact;
    EXPECT_EQ(r.contact.engaged_length, first->engaged_length);
    EXPECT_EQ(r.contact.normal_force, first->normal_force);
    EXPECT_EQ(r.contact.tilt, first->tilt);
  }
  // The robot goes 40 mm in, far past the frontier.
  ASSERT_GT(held, 1000u);
  EXPECT_GT(deepest, 0.030);
  EXPECT_EQ(prepared.analyzer->prepared_depth(), frontier);
  // The frontier's own state, as the analyzer answers it there.
  MatingPose at;
  at.depth = frontier;
  ContactState there;
  prepared.analyzer->Evaluate(at, &there);
  EXPECT_EQ(first->engaged_length, there.engaged_length);

  RunInfo info;
  info.rate = scene.run.rate;
  const nlohmann::json summary = MakeSummary(info, trace, RunStats{});
  EXPECT_EQ(summary["held_for_prepare"]["ticks"], held);
  EXPECT_EQ(summary["held_for_prepare"]["deepest_mm"], deepest * 1e3);
  EXPECT_EQ(summary["held_for_prepare"]["longest_s"], static_cast<double>(longest) / info.rate);

  // Released, the worker finishes; the same pose then feels its own state.
  EXPECT_GT(asked.load(), 0);
  go.store(true);
  prepared.FinishPreparing();
  EXPECT_EQ(prepared.analyzer->prepared_depth(), std::numeric_limits<double>::infinity());
}

// The worker appends steps while the ticks read them (the case ThreadSanitizer is run on); the
// summary says when the scene was ready and when whole, and whether a tick was held (timing is a
// measurement here, never asserted).
TEST(ProgressiveRunRealTime, PreparesTheRestWhileTheTicksRun) {
  Scene scene = LoadShipped("fits-20mm-h7n6");
  scene.run.duration = 0.5;
  RunOptions options;
  options.clock = ClockMode::kRealTime;
  const RunResult result = RunScene(std::move(scene), options);
  EXPECT_EQ(result.stats.ticks, 500u);
  const nlohmann::json& summary = result.summary;
  EXPECT_GT(summary["ready_to_touch_ms"].get<double>(), 0.0);
  EXPECT_GE(summary["prepare_s"]["total"].get<double>() * 1e3,
            summary["ready_to_touch_ms"].get<double>());
  EXPECT_TRUE(summary["held_for_prepare"].contains("ticks"));
}

TEST(ProgressiveRunInterrupted, ARealTimeRunInterruptedWhileItsWorkerWaitsStopsTheWorker) {
  std::atomic<bool> stop{false};
  std::atomic<int> asked{0};
  StopAtTick observer(&stop, 20);
  RunOptions options;
  options.clock = ClockMode::kRealTime;
  options.stop = &stop;
  options.observer = &observer;
  // The worker never prepares a step: only a stop ends it.
  options.prepare_pace = [&] {
    asked.fetch_add(1);
    return false;
  };
  EXPECT_THROW(RunScene(LoadShipped("fits-20mm-h7n6"), options), Interrupted);
  EXPECT_GT(asked.load(), 0);  // the worker was alive, and RunScene returned: it was joined
}

}  // namespace
}  // namespace fitfeel
