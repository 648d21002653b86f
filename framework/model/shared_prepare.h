#pragma once

#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <typeinfo>

#include "framework/core/export.h"

namespace fitfeel {

// What the prepares of many runs of one scene hand each other: results that depend only on the
// scene, never on a drawn part (the elements of an elastic model, a law's tables), computed by
// the first prepare that asks and read by the others. A fit study holds one for all its pairs, so
// a pair pays only for what its own parts change. Prepare-time only; safe to use from several
// threads at once. A value is read-only once stored (run-state.md: nothing a run shares is
// written).
class FITFEEL_API SharedPrepare {
 public:
  SharedPrepare();
  ~SharedPrepare();
  SharedPrepare(const SharedPrepare&) = delete;
  SharedPrepare& operator=(const SharedPrepare&) = delete;

  // The value stored under `key`, made by `make` when no caller has stored one. A caller asking
  // while another makes it waits for that one's result (or its exception), so each value is made
  // once. `key` must spell out every input of `make` exactly (bit patterns, not rounded text):
  // two prepares then share a value only where they would have computed the same one.
  template <typename T>
  std::shared_ptr<const T> Get(const std::string& key, const std::function<T()>& make) {
    return std::static_pointer_cast<const T>(
        Find(std::string(typeid(T).name()) + '\n' + key,
             [&make]() -> std::shared_ptr<const void> { return std::make_shared<T>(make()); }));
  }

  // Values made so far (for tests).
  int size() const;

 private:
  using Value = std::shared_ptr<const void>;
  Value Find(const std::string& key, const std::function<Value()>& make);

  mutable std::mutex mutex_;
  std::map<std::string, std::shared_future<Value>> values_;
};

// Appends the exact bit pattern of `x` to a SharedPrepare key.
FITFEEL_API void AppendKey(std::string* key, double x);

}  // namespace fitfeel
