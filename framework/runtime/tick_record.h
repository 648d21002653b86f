#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "framework/core/wrench.h"
#include "framework/model/contact_analyzer.h"
#include "framework/runtime/stage.h"
#include "framework/safety/safety_chain.h"

namespace fitfeel {

// What one tick leaves behind in the run's pre-allocated buffer (one row of trace.csv).
struct TickRecord {
  double time = 0.0;  // scheduled time of the tick, s
  // Simulated moving part's leading end (the device's, or the proxy's when coupled), scene frame,
  // m.
  Eigen::Vector3d position{0.0, 0.0, 0.0};
  MatingPose pose;
  ContactState contact;
  Wrench wrench;              // model wrench on the moving part after the finite guard, N / N*m
  Wrench device_wrench;       // what the safety chain wrote to the device, device N / N*m
  ElasticLimitCheck elastic;  // the contact's stresses against yield (DIN 7190)
  // A joint of several features: each feature's axial force (StageOutput::feature_axial).
  int feature_count = 0;
  std::array<double, kMaxJointFeatures> feature_axial{};
  ScrewOutput screw;        // a screw's joint (StageOutput::screw)
  double stiffness = 0.0;   // radial contact stiffness handed to the device, N/m
  double compute_us = 0.0;  // wall time from device read to device write, us (a measurement)
  StageId stage = StageId::kPositioning;
  bool guard_fault = false;  // the stage produced a non-finite wrench; zero was sent
  // The device state was not finite or beyond physical bounds: the last sane one was held and
  // zero force sent.
  bool device_fault = false;
};

// Order statistics of a sample, in microseconds.
struct Percentiles {
  double p50 = 0.0;
  double p99 = 0.0;
  double max = 0.0;
};

struct RunStats {
  std::uint64_t ticks = 0;
  std::uint64_t planned_ticks = 0;
  std::uint64_t deadline_misses = 0;  // real time: ticks that finished after the next deadline
  // Real time: ticks that woke more than a period late and sent zero, the next ones ramping back
  // (OverrunGuard).
  std::uint64_t overruns = 0;
  std::uint64_t guard_faults = 0;  // ticks whose wrench was not finite
  // Ticks whose device state was not finite or outside physical bounds (physical_bounds.h): the
  // last sane state was held and zero force sent.
  std::uint64_t device_faults = 0;
  // Streamed runs under a real-time clock: rows the writer had no room for (the tick never waits);
  // they are missing from trace.csv, recording.csv and summary.json's statistics.
  std::uint64_t dropped_rows = 0;
  Percentiles compute_us;  // per-tick compute time
  // Per-tick contact evaluations (StageOutput::contact_evaluations): the tick's cost counted,
  // the same on every machine and run, where compute_us is the machine's.
  Percentiles contact_evaluations;
  bool realtime = false;
  Percentiles jitter_us;       // real time: |actual period - nominal period|
  Percentiles lateness_us;     // real time: wake-up after the absolute deadline
  double wall_seconds = 0.0;   // duration of the loop
  double achieved_rate = 0.0;  // ticks / wall_seconds, Hz
  std::string realtime_note;   // what the real-time set-up got (SCHED_FIFO, slack)
  SafetyReport safety;         // what the safety chain did
};

}  // namespace fitfeel
