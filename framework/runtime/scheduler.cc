#include "framework/runtime/scheduler.h"

#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <thread>

#include "framework/core/error.h"
#include "framework/device/physical_bounds.h"

namespace fitfeel {
namespace {

std::int64_t NowNs() noexcept {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

timespec ToTimespec(std::int64_t ns) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(ns / 1000000000LL);
  ts.tv_nsec = static_cast<long>(ns % 1000000000LL);
  return ts;
}

// The loader refuses a run whose buffers exceed kMaxRunBufferBytes by these per-tick sizes: a
// streamed run keeps the compute time and, in real time, three stamps; a kept trace its records.
static_assert(4 * sizeof(double) <= kStreamBytesPerTick);
static_assert(sizeof(TickRecord) + 4 * sizeof(double) <= kTraceBytesPerTick);
static_assert(sizeof(RecordedSample) <= kRecordingBytesPerTick);

// Under the virtual clock the loop waits this long at a time for the writer to make room.
constexpr auto kRoomWait = std::chrono::microseconds(50);

// Priority of the real-time loop under SCHED_FIFO: above ordinary real-time helpers (IRQ threads
// run at 50 by default on PREEMPT_RT) and below the kernel's watchdogs at 99.
constexpr int kFifoPriority = 80;

// Sets up the calling thread for the 1 kHz loop and says what it got, in one line.
std::string SetUpRealTimeThread() {
  std::string note;
  // Default timer slack (50 us) would let the kernel defer each wake-up by that much.
  if (prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL) != 0) {
    note += "timer slack not set (" + std::string(std::strerror(errno)) + "); ";
  } else {
    note += "timer slack 1 ns; ";
  }
  sched_param param{};
  param.sched_priority = std::min(kFifoPriority, sched_get_priority_max(SCHED_FIFO));
  const int rc = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
  if (rc != 0) {
    note += "note: SCHED_FIFO not permitted (" + std::string(std::strerror(rc)) +
            "), running at normal priority: expect more jitter";
  } else {
    note += "SCHED_FIFO priority " + std::to_string(param.sched_priority);
  }
  return note;
}

// The stiffness the device handle meets, device N/m: with the coupling, the coupling spring in
// series with the (mapped) environment behind the quasi-static proxy; directly, the environment.
double DeviceStiffness(const SafetyChain& chain, double physical_stiffness) noexcept {
  const double k_e = physical_stiffness > 0.0 ? physical_stiffness * chain.stiffness_scale() : 0.0;
  if (chain.settings().coupling != CouplingMode::kSpringDamper) return k_e;
  const double k_c = chain.report().coupling_gains.stiffness;
  return k_e > 0.0 && k_c > 0.0 ? k_c * k_e / (k_c + k_e) : 0.0;
}

}  // namespace

SafetySettings RuntimeSafetySettings(const std::optional<SafetySection>& safety,
                                     const DeviceSpec& spec) {
  SafetySettings settings = safety ? safety->settings : SafetySettings{};
  const bool names_coupling = safety && safety->names_coupling;
  if (spec.max_force == std::numeric_limits<double>::infinity() && !names_coupling) {
    settings.coupling = CouplingMode::kDirect;
  }
  return settings;
}

Percentiles ComputePercentiles(std::vector<double> values) {
  Percentiles out;
  if (values.empty()) return out;
  const auto n = values.size();
  // Nearest-rank percentiles: the smallest value with at least p of the sample at or below it.
  auto rank = [n](double p) {
    const auto r = static_cast<std::size_t>(std::ceil(p * static_cast<double>(n)));
    return std::clamp<std::size_t>(r, 1, n) - 1;
  };
  const auto k50 = rank(0.50);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k50), values.end());
  out.p50 = values[k50];
  const auto k99 = rank(0.99);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k99), values.end());
  out.p99 = values[k99];
  out.max = *std::max_element(values.begin(), values.end());
  return out;
}

SchedulerSettings SceneSchedulerSettings(const Scene& scene) {
  SchedulerSettings settings;
  settings.rate = scene.run.rate;
  settings.duration = scene.run.duration;
  settings.clock = scene.run.clock;
  settings.part_motion = scene.part_motion;
  return settings;
}

double Scheduler::PeriodOf(const SchedulerSettings& settings) {
  if (!(settings.rate > 0.0) || !std::isfinite(settings.rate) || settings.rate > 100000.0) {
    throw UserError("scheduler: rate must be in (0, 100 kHz], got " +
                    std::to_string(settings.rate) + " Hz");
  }
  return 1.0 / settings.rate;
}

Scheduler::Scheduler(Device& device, const Stage& positioning, const Stage& constrained,
                     const SchedulerSettings& settings)
    : device_(device),
      stages_{&positioning, &constrained},
      settings_(settings),
      period_(PeriodOf(settings)),
      part_motion_(settings.part_motion, period_) {
  if (positioning.id() != StageId::kPositioning || constrained.id() != StageId::kConstrained) {
    throw UserError("scheduler: stages given in the wrong order");
  }
  if (!(settings.duration > 0.0) || !std::isfinite(settings.duration)) {
    throw UserError("scheduler: duration must be a positive number of seconds");
  }
  device_clock_ = device.clock_owner() == ClockOwner::kDevice;
  const double ticks = std::round(settings.duration * settings.rate);
  if (ticks < 1.0) throw UserError("scheduler: the run is shorter than one tick");
  const double per_tick =
      settings.stream != nullptr
          ? kStreamBytesPerTick
          : kTraceBytesPerTick + (settings.record ? kRecordingBytesPerTick : 0.0);
  if (ticks * per_tick > kMaxRunBufferBytes) {
    throw UserError("scheduler: a run of " + std::to_string(settings.duration) + " s at " +
                    std::to_string(settings.rate) +
                    " Hz needs trace buffers of more than 2 GiB; shorten run.duration");
  }
  planned_ticks_ = static_cast<std::uint64_t>(ticks);
  run_.chain.Configure(settings.safety, device.spec(), period_);
  MakeStageStates();
  // Sized (and its pages touched) here, so that the loop never allocates or faults them in.
  compute_us_.assign(planned_ticks_, 0.0);
  evaluations_.assign(planned_ticks_, 0.0);
  if (settings.stream == nullptr) {
    trace_.resize(planned_ticks_);
    if (settings.record) recording_.resize(planned_ticks_);
  }
  if (device_clock_ || settings.clock == ClockMode::kRealTime) {
    wake_ns_.assign(planned_ticks_, 0.0);
    deadline_ns_.assign(planned_ticks_, 0.0);
    end_ns_.assign(planned_ticks_, 0.0);
  }
}

void Scheduler::Rewind() noexcept {
  if (settings_.stream == nullptr) {
    trace_.resize(planned_ticks_);  // within capacity: no allocation
    if (settings_.record) recording_.resize(planned_ticks_);
  }
  run_.chain_reset = true;
  run_.guard_faults = 0;
  run_.device_faults = 0;
  run_.dropped_rows = 0;
  run_.overrun.Reset();
  run_.wake_lateness = 0.0;
  run_.last_sane_device = DeviceState{};
  ticks_done_.store(0, std::memory_order_relaxed);
  run_.current = StageId::kPositioning;
  run_.output = StageOutput{};  // a run starts with no part pose of an earlier run
  run_.part_motion = part_motion_.MakeState();
}

void Scheduler::MakeStageStates() {
  for (std::size_t i = 0; i < stages_.size(); ++i) run_.stages[i] = stages_[i]->MakeState();
}

bool Scheduler::Tick(double time) noexcept {
  const std::uint64_t k = ticks_done_.load(std::memory_order_relaxed);
  if (k >= planned_ticks_ || !device_.active()) return false;
  if (settings_.stop != nullptr && settings_.stop->load(std::memory_order_relaxed)) return false;
  const std::int64_t start = NowNs();
  RunState& run = run_;
  device_.Read(time, &run.device);
  // An absurd device state (a failing encoder, a driver bug) never reaches the law, the chain or
  // the outputs: the last sane state stands in for it and the device gets zero force below.
  const bool device_fault = !DeviceStateInBounds(run.device);
  if (device_fault) {
    run.device = run.last_sane_device;
    ++run.device_faults;
  } else {
    run.last_sane_device = run.device;
  }
  part_motion_.Place(run.device, run.part_motion, &run.part);
  if (run.chain_reset) {
    run.chain.Reset(run.part);  // proxy at the handle, energy and counters at zero
    run.chain_reset = false;
  }
  run.chain.SimulatedState(run.part, &run.law_state);
  const StageId stage = run.current;
  const auto index = static_cast<std::size_t>(stage);
  stages_[index]->Evaluate(run.law_state, run.stages[index].get(), &run.output);
  const StageOutput& output = run.output;

  // The chain zeroes (and counts) a non-finite wrench itself; the guard keeps the trace's physical
  // wrench finite too and flags the tick.
  run.chain.SetEnvironmentStiffness(output.stiffness);
  // A device that owns the clock ticks when its servo thread does: the coupling and the observer
  // integrate over the period it measured, not the nominal one.
  double dt = period_;
  if (device_clock_ && k > 0 && time > run.last_time) dt = time - run.last_time;
  run.last_time = time;
  Wrench device_wrench = run.chain.Apply(output.wrench, run.part, dt);
  if (device_fault) device_wrench = Wrench{};
  // Real time only: after a missed deadline, zero and then a ramp (overrun_guard.h). A device's
  // own clock shows the miss as a long period; the scheduler's clock as a late wake-up.
  if (stats_.realtime) {
    const double lateness = device_clock_ ? dt - period_ : run.wake_lateness;
    const double factor = run.overrun.Factor(lateness, period_);
    if (factor < 1.0) {
      device_wrench.force *= factor;
      device_wrench.torque *= factor;
    }
  }
  const bool fault = !output.wrench.AllFinite();
  if (fault) {
    run.output.wrench.SetZero();
    ++run.guard_faults;
  }
  ContactFeedback feedback;
  feedback.stiffness = DeviceStiffness(run.chain, output.stiffness);
  // Coupled, the part meets the coupling spring, not the surface: its free way is unknown.
  const bool coupled = run.chain.settings().coupling == CouplingMode::kSpringDamper;
  feedback.gap = coupled ? std::numeric_limits<double>::infinity() : output.gap;
  feedback.gap_direction = output.gap_direction;
  device_.SetEnvironmentStiffness(feedback.stiffness);
  device_.Write(device_wrench);
  part_motion_.Step(run.device, device_wrench, feedback, &run.part_motion);
  const std::int64_t end = NowNs();

  const bool streaming = settings_.stream != nullptr;
  TickRecord& record = streaming ? run.row.tick : trace_[k];
  record.time = time;
  record.position = run.law_state.position;  // the simulated part: the proxy when coupled
  record.pose = output.pose;
  record.contact = output.contact;
  record.wrench = output.wrench;
  record.device_wrench = device_wrench;
  record.elastic = output.elastic;
  record.feature_count = output.feature_count;
  record.feature_axial = output.feature_axial;
  record.screw = output.screw;
  record.stiffness = output.stiffness;
  record.compute_us = static_cast<double>(end - start) * 1e-3;
  record.stage = stage;
  record.guard_fault = fault;
  record.device_fault = device_fault;
  compute_us_[k] = record.compute_us;
  evaluations_[k] = output.contact_evaluations;
  if (settings_.record) {
    RecordedSample& sample = streaming ? run.row.sample : recording_[k];
    sample.time = time;
    sample.position = run.device.position;
    sample.orientation = run.device.orientation;
    sample.velocity = run.device.velocity;
    sample.angular_velocity = run.device.angular_velocity;
    sample.buttons = run.device.buttons;
    sample.commanded = device_wrench;
    sample.delivered = run.device.delivered;
    sample.load = part_motion_.LoadAt(run.device);
  }
  if (!wake_ns_.empty()) {
    wake_ns_[k] = static_cast<double>(start);
    end_ns_[k] = static_cast<double>(end);
  }
  if (streaming) {
    run.row.index = k;
    run.row.has_sample = settings_.record;
    // Never waits: under the virtual clock the loop made room before the tick; in real time a
    // full ring costs this row, counted.
    if (!settings_.stream->TryPush(run.row)) ++run.dropped_rows;
  }
  if (observer_ != nullptr) observer_->OnTick(record);
  run.current = output.next;
  ticks_done_.store(k + 1, std::memory_order_relaxed);
  return true;
}

void Scheduler::Run() {
  Rewind();
  MakeStageStates();
  stats_ = RunStats{};
  stats_.planned_ticks = planned_ticks_;
  const std::int64_t start = NowNs();
  if (device_.clock_owner() == ClockOwner::kDevice) {
    RunDeviceClock();
  } else if (settings_.clock == ClockMode::kRealTime) {
    RunRealTime();
  } else {
    RunVirtual();
  }
  stats_.wall_seconds = static_cast<double>(NowNs() - start) * 1e-9;
  ComputeStats();
}

void Scheduler::RunVirtual() {
  SpscRing<StreamRow>* stream = settings_.stream;
  for (std::uint64_t k = 0; k < planned_ticks_; ++k) {
    // Virtual time has no deadline: wait for the writer rather than lose a row.
    if (stream != nullptr) {
      while (!stream->HasRoom()) std::this_thread::sleep_for(kRoomWait);
    }
    // k / rate rather than an accumulated sum: no drift, and the same double on every run.
    if (!Tick(static_cast<double>(k) / settings_.rate)) break;
  }
}

void Scheduler::RunRealTime() {
  stats_.realtime = true;
  std::string note;
  int sleep_error = 0;
  // A thread of our own, so that SCHED_FIFO and the timer slack apply to the loop alone.
  std::thread loop([&] {
    note = SetUpRealTimeThread();
    // The first deadline is one period ahead: the set-up above is not part of the first tick.
    const std::int64_t origin = NowNs() + static_cast<std::int64_t>(std::llround(1e9 * period_));
    for (std::uint64_t k = 0; k < planned_ticks_; ++k) {
      // Deadlines from the origin, never accumulated: rounding cannot drift over a long run.
      const std::int64_t deadline =
          origin + std::llround(static_cast<double>(k) * 1e9 / settings_.rate);
      const timespec when = ToTimespec(deadline);
      int rc;
      do {
        rc = clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &when, nullptr);
      } while (rc == EINTR);
      if (rc != 0) {
        sleep_error = rc;
        break;
      }
      deadline_ns_[k] = static_cast<double>(deadline);
      run_.wake_lateness = static_cast<double>(NowNs() - deadline) * 1e-9;
      if (!Tick(static_cast<double>(k) / settings_.rate)) break;
    }
  });
  loop.join();
  stats_.realtime_note = note;
  if (sleep_error != 0) {
    throw std::runtime_error("clock_nanosleep failed: " + std::string(std::strerror(sleep_error)));
  }
}

void Scheduler::RunDeviceClock() {
  stats_.realtime = true;
  stats_.realtime_note = "clock owned by the device's servo thread";
  device_.RunServoLoop(settings_.duration, [this](double time) { return Tick(time); });
}

RunStats Scheduler::StatsSoFar() const {
  const std::uint64_t n = ticks_done_.load(std::memory_order_relaxed);
  RunStats s = stats_;
  s.safety = run_.chain.report();
  s.ticks = n;
  s.planned_ticks = planned_ticks_;
  s.guard_faults = run_.guard_faults;
  s.device_faults = run_.device_faults;
  s.dropped_rows = run_.dropped_rows;
  s.overruns = run_.overrun.overruns();
  const auto done = static_cast<std::ptrdiff_t>(std::min<std::uint64_t>(n, compute_us_.size()));
  s.compute_us =
      ComputePercentiles(std::vector<double>(compute_us_.begin(), compute_us_.begin() + done));
  s.contact_evaluations =
      ComputePercentiles(std::vector<double>(evaluations_.begin(), evaluations_.begin() + done));
  return s;
}

void Scheduler::ComputeStats() {
  const std::uint64_t n = ticks_done_.load(std::memory_order_relaxed);
  if (settings_.stream == nullptr) {
    trace_.resize(n);  // shrinking never allocates
    if (!recording_.empty()) recording_.resize(n);
  }
  stats_ = StatsSoFar();
  stats_.achieved_rate = stats_.wall_seconds > 0.0 ? n / stats_.wall_seconds : 0.0;
  if (!stats_.realtime) return;

  const double period_ns = 1e9 * period_;
  const bool own_clock = device_.clock_owner() != ClockOwner::kDevice;
  std::vector<double> jitter;
  std::vector<double> lateness;
  for (std::uint64_t k = 0; k < n; ++k) {
    if (k > 0) jitter.push_back(std::abs((wake_ns_[k] - wake_ns_[k - 1]) - period_ns) * 1e-3);
    // A tick misses its deadline when it is not done before the next one is due. Under the
    // device's clock, the next call is due one period after this one began.
    const double due = (own_clock ? deadline_ns_[k] : wake_ns_[k]) + period_ns;
    if (end_ns_[k] > due) ++stats_.deadline_misses;
    if (own_clock) lateness.push_back((wake_ns_[k] - deadline_ns_[k]) * 1e-3);
  }
  stats_.jitter_us = ComputePercentiles(std::move(jitter));
  stats_.lateness_us = ComputePercentiles(std::move(lateness));
}

}  // namespace fitfeel
