// Cost of one scheduler tick with a trivial stage and device: the framework's own overhead per
// tick (device read and write through the virtual interface, stage dispatch, the safety chain,
// record into the pre-allocated buffer, two monotonic clock reads), i.e. what is left of the 1 ms
// for the contact model. Three variants: the pass-through chain of a device without limits (the
// simulated robot), and a PHANTOM Desktop's chain rendering directly and through the virtual
// coupling, against a stiff wall the handle presses into. A fourth runs the pass-through tick
// with the live viewer's publisher attached and a reader popping it at 60 Hz (fitfeel view).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>

#include "framework/device/device.h"
#include "framework/device/device_specs.h"
#include "framework/runtime/stage.h"
#include "framework/runtime/scheduler.h"
#include "framework/view/tick_publisher.h"

namespace fitfeel {
namespace {

class StillDevice final : public Device {
 public:
  explicit StillDevice(DeviceSpec spec) : spec_(std::move(spec)) {}
  DeviceSpec DoSpec() const override { return spec_; }

 protected:
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double time, DeviceState* out) noexcept override {
    out->time = time;
    // 1 mm into the wall, with a small tremor so that the coupling and observer do real work.
    out->position.y() = 1e-3 + 1e-5 * static_cast<double>(++reads_ % 7);
    out->velocity.y() = 1e-3;
  }
  void DoWrite(const Wrench& w) noexcept override { benchmark::DoNotOptimize(w.force.data()); }

 private:
  DeviceSpec spec_;
  unsigned reads_ = 0;
};

// A wall at y = 0 of 1 N/mm (physical), reported with its stiffness as the constrained stage does.
class WallStage final : public Stage {
 public:
  explicit WallStage(StageId id) : id_(id) {}
  StageId DoId() const override { return id_; }

 protected:
  void DoEvaluate(const PartState& d, StageState*, StageOutput* out) const noexcept override {
    out->wrench.SetZero();
    const double depth = d.position.y();
    out->wrench.force.y() = depth > 0.0 ? -1e3 * depth : 0.0;
    out->stiffness = depth > 0.0 ? 1e3 : 0.0;
    out->next = StageId::kConstrained;
  }

 private:
  StageId id_;
};

DeviceSpec Unlimited() {
  DeviceSpec spec;
  spec.model = "benchmark unlimited device";
  spec.max_force = std::numeric_limits<double>::infinity();
  spec.max_continuous_force = spec.max_force;
  spec.max_stiffness = spec.max_force;
  spec.workspace = Eigen::Vector3d::Constant(1.0);
  return spec;
}

void TickLoop(benchmark::State& state, const DeviceSpec& spec, const SafetySettings& safety,
              TickObserver* observer = nullptr) {
  StillDevice device(spec);
  device.Start(1e-3);
  const WallStage positioning(StageId::kPositioning);
  const WallStage constrained(StageId::kConstrained);
  SchedulerSettings settings{1000.0, 10.0, ClockMode::kVirtual};
  settings.safety = safety;
  Scheduler scheduler(device, positioning, constrained, settings);
  scheduler.set_observer(observer);
  double time = 0.0;
  // Per-tick times for the p50 / p99 counters (the viewer's promise is about the tail, which a mean
  // hides); the two clock reads cost the same in every variant.
  std::vector<double> tick_ns;
  tick_ns.reserve(static_cast<std::size_t>(state.max_iterations));
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    if (!scheduler.Tick(time)) {
      state.PauseTiming();
      scheduler.Rewind();
      state.ResumeTiming();
      scheduler.Tick(time);
    }
    tick_ns.push_back(
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count());
    time += 1e-3;
  }
  if (tick_ns.empty()) return;
  auto percentile = [&](double q) {
    const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(tick_ns.size() - 1));
    std::nth_element(tick_ns.begin(), tick_ns.begin() + k, tick_ns.end());
    return tick_ns[static_cast<std::size_t>(k)];
  };
  state.counters["p50_ns"] = percentile(0.50);
  state.counters["p99_ns"] = percentile(0.99);
}

void BM_SchedulerTickPassThrough(benchmark::State& state) {
  TickLoop(state, Unlimited(), RuntimeSafetySettings(std::nullopt, Unlimited()));
}
BENCHMARK(BM_SchedulerTickPassThrough);

void BM_SchedulerTickPassThroughPublished(benchmark::State& state) {
  view::TickPublisher publisher;
  std::atomic<bool> done{false};
  std::thread reader([&] {
    view::ViewSample sample;
    while (!done.load(std::memory_order_relaxed)) {
      publisher.PopLatest(&sample);
      benchmark::DoNotOptimize(sample);
      std::this_thread::sleep_for(std::chrono::microseconds(16667));
    }
  });
  TickLoop(state, Unlimited(), RuntimeSafetySettings(std::nullopt, Unlimited()), &publisher);
  done = true;
  reader.join();
  state.counters["dropped"] = static_cast<double>(publisher.dropped());
}
BENCHMARK(BM_SchedulerTickPassThroughPublished);

void BM_SchedulerTickDirect(benchmark::State& state) {
  SafetySettings safety;
  safety.coupling = CouplingMode::kDirect;
  safety.force_scale = 0.01;
  TickLoop(state, LookupDeviceSpec("PHANTOM Desktop"), safety);
}
BENCHMARK(BM_SchedulerTickDirect);

void BM_SchedulerTickCoupled(benchmark::State& state) {
  SafetySettings safety;
  safety.coupling = CouplingMode::kSpringDamper;
  safety.force_scale = 0.01;
  TickLoop(state, LookupDeviceSpec("PHANTOM Desktop"), safety);
}
BENCHMARK(BM_SchedulerTickCoupled);

}  // namespace
}  // namespace fitfeel
