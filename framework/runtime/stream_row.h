#pragma once

#include <cstdint>

#include "framework/device/recording.h"
#include "framework/runtime/tick_record.h"

namespace fitfeel {

// What one tick hands to the run's writer thread through the ring: a fixed-size copy, no pointer
// into the scheduler's state.
struct StreamRow {
  std::uint64_t index = 0;  // the tick's number from 0
  TickRecord tick;
  RecordedSample sample;  // the device stream, when the run records
  bool has_sample = false;
};

}  // namespace fitfeel
