#pragma once

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <thread>
#include <vector>

#include "framework/core/export.h"
#include "framework/model/contact_analyzer.h"

namespace fitfeel {

// The rest of a progressive prepare (ContactAnalyzer::PrepareAhead): the depth steps each
// analyzer has left after its ready ones, in depth order and analyzer after analyzer (the datum
// feature's first), on one thread of its own while the ticks read what is prepared; or finished
// by its owner (Finish). Its destructor stops and joins the thread, however the run ends.
class FITFEEL_API PrepareWorker {
 public:
  using Clock = std::chrono::steady_clock;

  // `analyzers` are borrowed and must outlive it; `start`: when their prepare began (the times
  // it reports count from there). With `thread`, the worker thread starts at once; `pace`, a test
  // hook (may be empty), is asked before each step and, while it answers false, the thread waits
  // (a millisecond at a time, stopping when asked).
  PrepareWorker(std::vector<ContactAnalyzer*> analyzers, Clock::time_point start, bool thread,
                std::function<bool()> pace);
  ~PrepareWorker();
  PrepareWorker(const PrepareWorker&) = delete;
  PrepareWorker& operator=(const PrepareWorker&) = delete;

  // Stops the thread after its current step, rethrows what a step threw there, and prepares
  // what is left on the calling thread (ContactAnalyzer::FinishPrepare). Returns the seconds
  // from the start until every table was whole.
  double Finish();
  // Whether the thread has prepared every table (any thread may ask).
  bool whole() const { return whole_.load(std::memory_order_acquire); }

 private:
  void Run() noexcept;

  std::vector<ContactAnalyzer*> analyzers_;
  Clock::time_point start_;
  std::function<bool()> pace_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> whole_{false};
  double whole_seconds_ = 0.0;  // written by the thread before whole_
  std::exception_ptr error_;    // what a step threw on the thread; read after the join
  std::thread thread_;
};

}  // namespace fitfeel
