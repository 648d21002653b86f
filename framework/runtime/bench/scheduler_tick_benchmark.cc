// Cost of one scheduler tick with a trivial stage and device: the framework's own overhead per
// tick (device read and write through the virtual interface, stage dispatch, wrench guard, record
// into the pre-allocated buffer, two monotonic clock reads), i.e. what is left of the 1 ms for the
// contact model.
#include <benchmark/benchmark.h>

#include "framework/device/device.h"
#include "framework/device/stage.h"
#include "framework/runtime/scheduler.h"

namespace fitfeel {
namespace {

class StillDevice final : public Device {
 public:
  DeviceSpec spec() const override { return {}; }

 protected:
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double time, DeviceState* out) noexcept override {
    out->time = time;
    out->position.y() = 1e-3;
  }
  void DoWrite(const Wrench& w) noexcept override { benchmark::DoNotOptimize(w.force.data()); }
};

class ConstantStage final : public Stage {
 public:
  explicit ConstantStage(StageId id) : id_(id) {}
  StageId id() const override { return id_; }

 protected:
  void DoEvaluate(const DeviceState& d, StageOutput* out) const noexcept override {
    out->wrench.SetZero();
    out->wrench.force.y() = -d.position.y();
    out->next = StageId::kConstrained;
  }

 private:
  StageId id_;
};

void BM_SchedulerTick(benchmark::State& state) {
  StillDevice device;
  device.Start(1e-3);
  const ConstantStage positioning(StageId::kPositioning);
  const ConstantStage constrained(StageId::kConstrained);
  Scheduler scheduler(device, positioning, constrained, {1000.0, 10.0, ClockMode::kVirtual});
  double time = 0.0;
  for (auto _ : state) {
    if (!scheduler.Tick(time)) {
      state.PauseTiming();
      scheduler.Rewind();
      state.ResumeTiming();
      scheduler.Tick(time);
    }
    time += 1e-3;
  }
}
BENCHMARK(BM_SchedulerTick);

}  // namespace
}  // namespace fitfeel
