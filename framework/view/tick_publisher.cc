#include "framework/view/tick_publisher.h"

namespace fitfeel::view {

TickPublisher::TickPublisher(std::size_t capacity, Role moving)
    : ring_(capacity), moving_(moving) {}

void TickPublisher::OnTick(const TickRecord& record) noexcept {
  if (!ring_.TryPush(MakeViewSample(record, ticks_, moving_))) {
    dropped_.fetch_add(1, std::memory_order_relaxed);
  }
  ++ticks_;
}

void TickPublisher::OnRecord(const TickRecord& record, std::uint64_t index) {
  building_.push_back(MakeViewSample(record, index, moving_));
}

void TickPublisher::OnRunEnd() {
  std::lock_guard<std::mutex> lock(history_mutex_);
  history_ = std::move(building_);
  building_ = {};
}

bool TickPublisher::PopLatest(ViewSample* sample) noexcept { return ring_.PopLatest(sample); }

std::optional<std::vector<ViewSample>> TickPublisher::TakeHistory() {
  std::lock_guard<std::mutex> lock(history_mutex_);
  std::optional<std::vector<ViewSample>> out = std::move(history_);
  history_.reset();
  return out;
}

}  // namespace fitfeel::view
