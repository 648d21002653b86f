#pragma once

// A tick observer that sets a run's stop flag (RunOptions::stop) as an interrupt would.

#include <atomic>
#include <cstdint>

#include "framework/runtime/tick_observer.h"

namespace fitfeel::test_support {

// Sets the flag during the tick numbered `at` (from 1), as a signal handler would between two
// ticks: the tick under way completes, the next one does not start.
class StopAtTick final : public TickObserver {
 public:
  StopAtTick(std::atomic<bool>* flag, std::uint64_t at) : flag_(flag), at_(at) {}
  void OnTick(const TickRecord&) noexcept override {
    if (++ticks_ == at_) flag_->store(true);
  }

 private:
  std::atomic<bool>* flag_;
  std::uint64_t at_;
  std::uint64_t ticks_ = 0;
};

}  // namespace fitfeel::test_support
