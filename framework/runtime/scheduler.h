#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "framework/core/export.h"
#include "framework/core/spsc_ring.h"
#include "framework/device/device.h"
#include "framework/device/recording.h"
#include "framework/runtime/stage.h"
#include "framework/runtime/overrun_guard.h"
#include "framework/runtime/part_motion.h"
#include "framework/runtime/stream_row.h"
#include "framework/runtime/tick_observer.h"
#include "framework/runtime/tick_record.h"
#include "framework/safety/safety_chain.h"
#include "framework/scenario/scene.h"

namespace fitfeel {

struct SchedulerSettings {
  double rate = 1000.0;   // Hz
  double duration = 0.0;  // s; the run has round(duration * rate) ticks
  ClockMode clock = ClockMode::kVirtual;
  // The safety chain between the stage's physical wrench and the device (RuntimeSafetySettings).
  SafetySettings safety = PassThroughSafety();
  // Fill a RecordedSample per tick into a buffer sized before the loop (run.outputs: recording),
  // or, when streaming, into the tick's row.
  bool record = false;
  // Borrowed. Set: every tick pushes its row here instead of keeping it (trace() and recording()
  // stay empty), so memory does not grow with the run; TraceStream drains it and states the
  // overrun policy. Null: the run's rows are kept in buffers sized before the loop.
  SpscRing<StreamRow>* stream = nullptr;
  // The moving part's radial motion under the device's load (the scene's `part_motion`).
  PartMotionSettings part_motion{};
  // Borrowed, may be null. Polled at each tick boundary (one relaxed load: no lock, no I/O): once
  // true the run ends there, before the next tick, as when the device becomes inactive. An
  // interrupted command's flag (InterruptFlag).
  const std::atomic<bool>* stop = nullptr;

  // Direct rendering at scale 1: with a device without limits (the simulated robot), the device
  // receives the stage's wrench bit for bit.
  static SafetySettings PassThroughSafety() {
    SafetySettings s;
    s.coupling = CouplingMode::kDirect;
    return s;
  }
};

// A scene's run as the scheduler takes it: rate, duration, clock and the part's motion; the
// safety settings need the started device's spec (RuntimeSafetySettings) and the outputs are the
// caller's.
FITFEEL_API SchedulerSettings SceneSchedulerSettings(const Scene& scene);

// The safety settings of a run: the scenario's `safety` section (absent: defaults), with one
// runtime default on top. A device without a motor (spec max_force +inf, the simulated robot and
// hand) renders directly unless the section names a `coupling`: no force it renders can hurt
// anyone, and the paper's traces were computed with the law at the device, so the chain must be a
// pass-through there (scale 1, direct, limits +inf, no passivity controller). Every other device
// gets the chain's own default, the virtual coupling.
FITFEEL_API SafetySettings RuntimeSafetySettings(const std::optional<SafetySection>& safety,
                                                 const DeviceSpec& spec);

// What the ticks of one run change, apart from the buffers they fill (see docs/run-state.md). The
// stages it serves stay immutable; the scheduler owns one of these per run.
struct RunState {
  std::array<std::unique_ptr<StageState>, 2> stages;  // indexed by StageId
  StageId current = StageId::kPositioning;
  DeviceState device;           // as the device reported it
  PartState part;               // the moving part: the device's state after PartMotion::Place
  PartState law_state;          // where the stage is evaluated (the proxy when coupled)
  PartMotionState part_motion;  // the part's radial dynamics
  StageOutput output;
  SafetyChain chain;
  bool chain_reset = true;  // reset the chain at the next tick's device state
  std::uint64_t guard_faults = 0;
  std::uint64_t device_faults = 0;  // device states outside physical bounds (held, zero force)
  std::uint64_t dropped_rows = 0;   // streamed rows the ring had no room for (real time)
  DeviceState last_sane_device;     // the newest device state inside physical bounds
  StreamRow row;                    // the tick's row when streaming
  OverrunGuard overrun;             // zero and ramp after a missed deadline (real time)
  double wake_lateness = 0.0;       // how late this tick woke after its deadline, s (real time)
  double last_time = 0.0;           // the previous tick's time (a device's clock: measured)
};

// One scheduler for every device. Per tick: device Read, the current stage's Evaluate, the wrench
// guard (and the safety chain's call site), device Write, record into a buffer sized before the
// loop. Two clocks:
//  - virtual: ticks run back to back with scheduled times k / rate; the physics (everything but
//    the measured compute time) is bit-for-bit deterministic for a scene and seed.
//  - real time: a thread of its own wakes at absolute deadlines (clock_nanosleep with
//    TIMER_ABSTIME on CLOCK_MONOTONIC), with 1 ns timer slack and SCHED_FIFO when permitted.
// A device that owns the clock (ClockOwner::kDevice) calls the same tick from its servo thread
// through Device::RunServoLoop.
//
// A scheduler is one run: it borrows immutable stages (which other schedulers may use at the same
// time from other threads) and a device of its own, and owns the run's state and buffers.
class FITFEEL_API Scheduler {
 public:
  // Devices and stages are borrowed and must outlive the scheduler; the device must be started.
  // Configures the safety chain from settings.safety, the device's spec and the period.
  // Throws UserError for a rate or duration out of range, a buffer too large to hold, or a device
  // spec or safety settings the chain refuses.
  Scheduler(Device& device, const Stage& positioning, const Stage& constrained,
            const SchedulerSettings& settings);

  // Runs every tick (or until the device becomes inactive or settings.stop is set) from fresh
  // stage states. Allocates before the loop only.
  void Run();

  // One tick at scheduled `time` (s): exposed for devices that own the clock and for benchmarks.
  // Returns false once every planned tick is done, the device is inactive or settings.stop is set.
  // No allocation, lock or I/O. A device state that is not finite or lies outside physical bounds (physical_bounds.h)
  // is not used: the last sane state is held, zero force is sent and the tick flagged.
  bool Tick(double time) noexcept;
  // An observer called at the end of every tick with its record (null: none). Borrowed; set it
  // before Run, not while the loop runs.
  void set_observer(TickObserver* observer) { observer_ = observer; }
  // Empties the buffer so that it can be filled again (benchmarks); keeps its capacity and the
  // stages' states (Run starts from fresh ones).
  void Rewind() noexcept;

  const std::vector<TickRecord>& trace() const { return trace_; }
  // The device stream, one sample per tick done; empty unless settings.record.
  const std::vector<RecordedSample>& recording() const { return recording_; }
  const SafetyChain& safety() const { return run_.chain; }
  const RunStats& stats() const { return stats_; }
  // The last tick's stage output (where the part was left), after Run.
  const StageOutput& last_output() const { return run_.output; }
  // The statistics of the ticks done so far, as a finished run reports them (not for the tick: it
  // allocates), for hosts that step the scheduler themselves and write outputs between steps.
  RunStats StatsSoFar() const;
  std::uint64_t planned_ticks() const { return planned_ticks_; }
  // Ticks done so far; safe to read from another thread (progress display).
  std::uint64_t ticks_done() const { return ticks_done_.load(std::memory_order_relaxed); }

 private:
  void RunVirtual();
  void RunRealTime();
  void RunDeviceClock();
  void ComputeStats();
  void MakeStageStates();
  // 1 / settings.rate; throws UserError for a rate out of range.
  static double PeriodOf(const SchedulerSettings& settings);

  Device& device_;
  std::array<const Stage*, 2> stages_;
  SchedulerSettings settings_;
  double period_ = 0.0;
  PartMotion part_motion_;
  bool device_clock_ = false;
  std::uint64_t planned_ticks_ = 0;

  RunState run_;
  std::vector<TickRecord> trace_;
  std::vector<RecordedSample> recording_;
  std::vector<double> compute_us_;   // every tick's compute time, for the run's statistics
  std::vector<double> evaluations_;  // every tick's contact evaluations, likewise
  // Real time only (empty under the virtual clock, whose statistics need no stamps).
  std::vector<double> wake_ns_;  // real time: absolute wake-up of each tick, ns
  std::vector<double> deadline_ns_;
  std::vector<double> end_ns_;
  std::atomic<std::uint64_t> ticks_done_{0};
  TickObserver* observer_ = nullptr;
  RunStats stats_;
};

// Median, 99th percentile and maximum of `values` (copied; empty gives zeros).
FITFEEL_API Percentiles ComputePercentiles(std::vector<double> values);

}  // namespace fitfeel
