#include "framework/model/shared_prepare.h"

#include <bit>
#include <cstdint>
#include <cstdio>

namespace fitfeel {

SharedPrepare::SharedPrepare() = default;
SharedPrepare::~SharedPrepare() = default;

int SharedPrepare::size() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<int>(values_.size());
}

SharedPrepare::Value SharedPrepare::Find(const std::string& key,
                                         const std::function<Value()>& make) {
  std::promise<Value> promise;
  std::shared_future<Value> future;
  bool maker = false;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = values_.find(key);
    if (it != values_.end()) {
      future = it->second;
    } else {
      future = promise.get_future().share();
      values_.emplace(key, future);
      maker = true;
    }
  }
  // Made outside the lock, so that other keys are made and read meanwhile.
  if (maker) {
    try {
      promise.set_value(make());
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return future.get();
}

void AppendKey(std::string* key, double x) {
  char text[20];
  std::snprintf(text, sizeof(text), "%016llx,",
                static_cast<unsigned long long>(std::bit_cast<std::uint64_t>(x)));
  *key += text;
}

}  // namespace fitfeel
