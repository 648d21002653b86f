#include "framework/runtime/prepare_worker.h"

#include <utility>

namespace fitfeel {

PrepareWorker::PrepareWorker(std::vector<ContactAnalyzer*> analyzers, Clock::time_point start,
                             bool thread, std::function<bool()> pace)
    : analyzers_(std::move(analyzers)), start_(start), pace_(std::move(pace)) {
  if (thread) thread_ = std::thread([this] { Run(); });
}

PrepareWorker::~PrepareWorker() {
  stop_.store(true, std::memory_order_relaxed);
  if (thread_.joinable()) thread_.join();
}

void PrepareWorker::Run() noexcept {
  try {
    for (ContactAnalyzer* analyzer : analyzers_) {
      while (!stop_.load(std::memory_order_relaxed)) {
        if (pace_ && !pace_()) {
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
          continue;
        }
        // One step at a time: a stop waits for one step at most.
        if (!analyzer->PrepareAhead(1)) break;
      }
    }
    if (stop_.load(std::memory_order_relaxed)) return;
    whole_seconds_ = std::chrono::duration<double>(Clock::now() - start_).count();
    whole_.store(true, std::memory_order_release);
  } catch (...) {
    error_ = std::current_exception();
  }
}

double PrepareWorker::Finish() {
  stop_.store(true, std::memory_order_relaxed);
  if (thread_.joinable()) thread_.join();
  if (error_) std::rethrow_exception(error_);
  if (whole()) return whole_seconds_;
  for (ContactAnalyzer* analyzer : analyzers_) analyzer->FinishPrepare();
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

}  // namespace fitfeel
