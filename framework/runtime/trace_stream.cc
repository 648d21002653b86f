#include "framework/runtime/trace_stream.h"

#include <cerrno>
#include <chrono>
#include <system_error>

#include "framework/core/demand.h"
#include "framework/core/error.h"
#include "framework/core/os_reason.h"
#include "framework/core/temporary_files.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

// Text is handed to the file in blocks of this size: the writer's memory is bounded, and a
// block is large enough that the write calls cost nothing next to the formatting.
constexpr std::size_t kBlockBytes = std::size_t{1} << 20;

// How long the writer sleeps when the ring is empty: at 1 kHz, 0.2 ms leaves a fifth of a tick's
// rows waiting, far below the ring's capacity.
constexpr auto kIdleSleep = std::chrono::microseconds(200);

}  // namespace

TraceStream::TraceStream(const StreamOutputs& outputs, TickObserver* observer, std::size_t capacity)
    : outputs_(outputs), observer_(observer), ring_(capacity) {
  const bool any_file =
      !outputs_.dir.empty() && (outputs_.trace || outputs_.summary || outputs_.recording);
  if (!any_file) {
    outputs_.trace = outputs_.summary = false;
    outputs_.recording.reset();
  } else {
    const fs::path& dir = outputs_.dir;
    std::error_code ec;
    created_dir_ = !fs::exists(dir, ec);
    if (created_dir_ && !fs::create_directories(dir, ec) && ec) {
      throw UserError("cannot create output folder '" + dir.string() + "': " + ec.message());
    }
    if (!fs::is_directory(dir, ec)) {
      throw UserError("output path '" + dir.string() + "' is not a folder");
    }
    auto pending = [&](const std::string& name) {
      return Pending{TemporaryPathFor(dir / name), dir / name};
    };
    try {
      if (outputs_.trace) {
        trace_file_ = pending("trace.csv");
        errno = 0;
        trace_out_.open(trace_file_.temporary, std::ios::binary | std::ios::trunc);
        const int open_error = errno;
        if (!trace_out_) {
          throw UserError("cannot create '" + trace_file_.temporary.string() +
                          "': " + OsReason(open_error));
        }
        trace_text_.reserve(kBlockBytes + 4096);
        trace_text_ = TraceHeader(outputs_.features, outputs_.screw) + "\n";
      }
      if (outputs_.summary) summary_file_ = pending("summary.json");
      if (outputs_.recording) {
        recording_file_ = pending("recording.csv");
        recording_ =
            std::make_unique<RecordingWriter>(recording_file_.temporary, *outputs_.recording);
      }
    } catch (...) {
      Discard();
      throw;
    }
  }
  writer_ = std::thread([this] { Loop(); });
}

TraceStream::~TraceStream() {
  StopWriter();
  if (!finished_) Discard();
}

void TraceStream::StopWriter() {
  if (!writer_.joinable()) return;
  stop_.store(true, std::memory_order_release);
  writer_.join();
}

void TraceStream::Loop() {
  StreamRow row;
  for (;;) {
    // The stop flag is read before the last drain: a row pushed before the producer set it is
    // popped by that drain.
    const bool stopping = stop_.load(std::memory_order_acquire);
    bool any = false;
    while (ring_.TryPop(&row)) {
      Consume(row);
      any = true;
    }
    if (stopping) break;
    if (!any) std::this_thread::sleep_for(kIdleSleep);
  }
}

void TraceStream::Consume(const StreamRow& row) {
  rows_.fetch_add(1, std::memory_order_relaxed);
  builder_.Add(row.tick);
  if (!error_.empty()) return;  // a failed file: keep draining, write nothing more
  try {
    if (observer_ != nullptr) observer_->OnRecord(row.tick, row.index);
    if (outputs_.trace) {
      AppendTraceRow(&trace_text_, row.tick, static_cast<int>(outputs_.features.size()),
                     outputs_.screw);
      trace_text_ += '\n';
      if (trace_text_.size() >= kBlockBytes) FlushTrace();
    }
    if (recording_ && row.has_sample) recording_->Append(row.sample);
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

void TraceStream::FlushTrace() {
  trace_out_.write(trace_text_.data(), static_cast<std::streamsize>(trace_text_.size()));
  trace_text_.clear();
  if (!trace_out_) {
    throw UserError("cannot write '" + trace_file_.temporary.string() + "' (disk full?)");
  }
}

OutputPaths TraceStream::Finish(const RunInfo& info, const RunStats& stats,
                                nlohmann::json* summary) {
  FITFEEL_DEMAND(!finished_);
  StopWriter();
  OutputPaths paths;
  std::vector<Pending> renamed;
  try {
    if (!error_.empty()) throw UserError(error_);
    nlohmann::json j = builder_.Make(info, stats);
    if (outputs_.trace) {
      FlushTrace();
      trace_out_.close();
      if (!trace_out_) {
        throw UserError("cannot write '" + trace_file_.temporary.string() + "' (disk full?)");
      }
    }
    if (recording_) recording_->Finish();
    if (outputs_.summary) {
      std::ofstream out(summary_file_.temporary, std::ios::binary | std::ios::trunc);
      out << j.dump(2) << '\n';
      out.close();
      if (!out) throw UserError("cannot write '" + summary_file_.temporary.string() + "'");
    }
    std::error_code ec;
    for (const Pending* p : {&trace_file_, &summary_file_, &recording_file_}) {
      if (p->final.empty()) continue;
      fs::rename(p->temporary, p->final, ec);
      if (ec) {
        throw UserError("cannot move '" + p->temporary.string() + "' to '" + p->final.string() +
                        "': " + ec.message());
      }
      renamed.push_back(*p);
    }
    if (summary != nullptr) *summary = std::move(j);
  } catch (...) {
    std::error_code ec;
    for (const Pending& p : renamed) fs::remove(p.final, ec);
    Discard();
    finished_ = true;
    throw;
  }
  if (outputs_.trace) paths.trace = trace_file_.final;
  if (outputs_.summary) paths.summary = summary_file_.final;
  if (outputs_.recording) paths.recording = recording_file_.final;
  finished_ = true;
  return paths;
}

void TraceStream::Discard() noexcept {
  if (trace_out_.is_open()) trace_out_.close();
  recording_.reset();
  std::error_code ec;
  for (const Pending* p : {&trace_file_, &summary_file_, &recording_file_}) {
    if (!p->temporary.empty()) fs::remove(p->temporary, ec);
  }
  if (created_dir_) fs::remove(outputs_.dir, ec);  // only removes it if empty
}

}  // namespace fitfeel
