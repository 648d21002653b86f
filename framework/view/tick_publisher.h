#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

#include "framework/core/export.h"
#include "framework/core/spsc_ring.h"
#include "framework/runtime/tick_observer.h"
#include "framework/view/view_sample.h"

namespace fitfeel::view {

// Hands the tick's state to the viewer's server thread: OnTick (the tick thread) copies a
// ViewSample into a lock-free ring and never waits; when the ring is full the sample is dropped
// and counted. The server thread pops at display rate and keeps the newest. The records the run
// streams (OnRecord, on the run's writer thread) become, when the run ends, the history a finished
// run is scrubbed through.
class FITFEEL_API TickPublisher final : public TickObserver {
 public:
  // `capacity` samples (rounded up to a power of two): at 1 kHz and a 60 Hz reader, 17 are
  // waiting at a time; the default leaves the reader a second of slack. `moving`: the scene's
  // moving part, which decides the samples' frame (ViewSample).
  explicit TickPublisher(std::size_t capacity = 1024, Role moving = Role::kInner);

  void OnTick(const TickRecord& record) noexcept override;
  void OnRecord(const TickRecord& record, std::uint64_t index) override;
  void OnRunEnd() override;

  // Server side: the newest sample since the last call; false when none came.
  bool PopLatest(ViewSample* sample) noexcept;
  // Samples the ring had no room for (the reader fell a second behind).
  std::uint64_t dropped() const noexcept { return dropped_.load(std::memory_order_relaxed); }
  // The finished run's trace, once (nullopt before the run ends and after it was taken).
  std::optional<std::vector<ViewSample>> TakeHistory();

 private:
  SpscRing<ViewSample> ring_;
  Role moving_;
  std::uint64_t ticks_ = 0;  // producer only
  std::atomic<std::uint64_t> dropped_{0};
  std::mutex history_mutex_;  // between the run's thread at its end and the server thread
  std::optional<std::vector<ViewSample>> history_;
  std::vector<ViewSample> building_;  // the writer thread's, until OnRunEnd
};

}  // namespace fitfeel::view
