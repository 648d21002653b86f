#pragma once

// What a device saw during a run (faults, recoveries, calibration, measured rate): named values
// in the order the device gives them, written to summary.json's `device_report`. A plain type, so
// that the device interface carries no JSON library.
#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace fitfeel {

class DeviceReport {
 public:
  using Value = std::variant<bool, std::uint64_t, double, std::string>;
  struct Entry {
    std::string key;
    Value value;
  };

  // Adds (or replaces) one value.
  DeviceReport& Set(std::string key, Value value) {
    for (Entry& e : entries_) {
      if (e.key == key) {
        e.value = std::move(value);
        return *this;
      }
    }
    entries_.push_back(Entry{std::move(key), std::move(value)});
    return *this;
  }
  // The value under `key`, null when there is none.
  const Value* Find(const std::string& key) const {
    for (const Entry& e : entries_) {
      if (e.key == key) return &e.value;
    }
    return nullptr;
  }
  // True when `key` holds the boolean true.
  bool IsTrue(const std::string& key) const {
    const Value* v = Find(key);
    return v != nullptr && std::holds_alternative<bool>(*v) && std::get<bool>(*v);
  }

  bool empty() const { return entries_.empty(); }
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::vector<Entry> entries_;
};

}  // namespace fitfeel
