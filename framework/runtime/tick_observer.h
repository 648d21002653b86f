#pragma once

#include <cstdint>

#include "framework/runtime/tick_record.h"

namespace fitfeel {

// Something that watches a run from outside the tick (a live viewer). The scheduler calls OnTick
// once per tick from the tick's thread, after the tick's record is written: it must not block,
// lock, allocate, throw or do I/O (hand the record to another thread through a lock-free ring).
// RunScene streams every record to a writer thread (the run never holds its trace) and calls
// OnRecord there, in tick order, with the tick's index; OnRunEnd follows once the writer has seen
// the last record, on the run's own thread.
class TickObserver {
 public:
  virtual ~TickObserver() = default;
  virtual void OnTick(const TickRecord& record) noexcept = 0;
  virtual void OnRecord(const TickRecord& record, std::uint64_t index) {
    (void)record;
    (void)index;
  }
  virtual void OnRunEnd() {}
};

}  // namespace fitfeel
