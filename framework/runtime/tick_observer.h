#pragma once

#include <vector>

#include "framework/runtime/tick_record.h"

namespace fitfeel {

// Something that watches a run from outside the tick (a live viewer). The scheduler calls OnTick
// once per tick from the tick's thread, after the tick's record is written: it must not block,
// lock, allocate, throw or do I/O (hand the record to another thread through a lock-free ring).
// RunScene calls OnRunEnd once the loop has ended, on its own thread, with every tick's record.
class TickObserver {
 public:
  virtual ~TickObserver() = default;
  virtual void OnTick(const TickRecord& record) noexcept = 0;
  virtual void OnRunEnd(const std::vector<TickRecord>& trace) { (void)trace; }
};

}  // namespace fitfeel
