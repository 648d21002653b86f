#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "framework/core/export.h"
#include "framework/core/spsc_ring.h"
#include "framework/device/recording.h"
#include "framework/runtime/outputs.h"
#include "framework/runtime/stream_row.h"
#include "framework/runtime/tick_observer.h"

namespace fitfeel {

// What a streamed run writes into its output folder.
struct StreamOutputs {
  std::filesystem::path dir;  // empty: no file, only the summary's statistics
  bool trace = true;
  bool summary = true;
  std::optional<RecordingInfo> recording;  // set: write recording.csv with this header
  // A several-feature scene's features: a trace column of each one's axial force.
  std::vector<std::string> features;
  bool screw = false;  // a screw scene: the joint's columns (TraceHeader)
};

// The run's outputs written while it runs, so that memory stays bounded whatever its duration:
// the tick pushes a fixed-size StreamRow into a lock-free single-producer ring (ring()), and a
// writer thread of this object drains it, formats trace.csv and recording.csv rows into blocks of
// about 1 MiB written to temporary names in the folder, and gathers summary.json's statistics.
// Finish renames everything into place once the run is complete; a stream destroyed without a
// successful Finish (the run failed) removes its temporaries and a folder it created, so a failed
// run leaves no file behind.
//
// Overrun policy (the scheduler applies it): under the virtual clock the loop waits for room
// before a tick (virtual time has no deadline; the trace stays complete and bit-for-bit
// deterministic); under a real-time clock the tick never waits: a row that finds the ring full is
// dropped and counted (summary.json: dropped_rows).
class FITFEEL_API TraceStream {
 public:
  // Rows the ring holds: 16 s at 1 kHz before a stalled writer costs a row (about 11 MB).
  static constexpr std::size_t kDefaultCapacity = std::size_t{1} << 14;

  // Creates the folder (when files are asked for) and the temporary files and starts the writer.
  // `observer` (borrowed, may be null) gets OnRecord for every row on the writer thread. Throws
  // UserError when the folder or a file cannot be created (nothing is left behind).
  TraceStream(const StreamOutputs& outputs, TickObserver* observer = nullptr,
              std::size_t capacity = kDefaultCapacity);
  ~TraceStream();
  TraceStream(const TraceStream&) = delete;
  TraceStream& operator=(const TraceStream&) = delete;

  SpscRing<StreamRow>& ring() { return ring_; }

  // Waits for the writer to drain every row, then writes summary.json (from `info` and `stats`
  // with the streamed statistics) and renames the files into place. Returns the paths; `summary`
  // receives summary.json's content (also when no file is written). Throws UserError on any write
  // failure or a row the recording refuses, after removing everything. Call once.
  OutputPaths Finish(const RunInfo& info, const RunStats& stats, nlohmann::json* summary);

  // Rows the writer has taken so far (any thread).
  std::uint64_t rows_written() const { return rows_.load(std::memory_order_relaxed); }

 private:
  struct Pending {
    std::filesystem::path temporary;
    std::filesystem::path final;
  };

  void Loop();
  void Consume(const StreamRow& row);
  void FlushTrace();
  void StopWriter();
  void Discard() noexcept;

  StreamOutputs outputs_;
  TickObserver* observer_ = nullptr;
  SpscRing<StreamRow> ring_;
  bool created_dir_ = false;
  Pending trace_file_, summary_file_, recording_file_;
  std::ofstream trace_out_;
  std::string trace_text_;
  std::unique_ptr<RecordingWriter> recording_;
  SummaryBuilder builder_;
  std::string error_;  // the writer's first failure; it keeps draining without writing
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> rows_{0};
  std::thread writer_;
  bool finished_ = false;
};

}  // namespace fitfeel
