#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <new>
#include <string>
#include <type_traits>

#include "framework/core/error.h"

namespace fitfeel {

// A bounded single-producer single-consumer queue for handing records out of the tick: the
// producer (the tick thread) never blocks, locks or allocates; when the ring is full TryPush fails
// and the record is dropped (the producer counts what it drops), so a slow or absent consumer can
// never slow the tick. Capacity is fixed at construction (rounded up to a power of two).
//
// One thread may push and one other thread may pop at a time; the indices are monotonically
// increasing counters, so full and empty are told apart without a spare slot. T is a fixed-size
// record copied in and out by assignment into slots built once at construction: its copy must not
// allocate or throw (plain structs of numbers and fixed-size Eigen vectors, never a std::string).
template <typename T>
class SpscRing {
  static_assert(std::is_default_constructible_v<T> && std::is_copy_assignable_v<T>,
                "SpscRing holds default-constructible, copy-assignable records");

 public:
  // Throws UserError for a capacity of 0 or above 2^30 records.
  explicit SpscRing(std::size_t capacity) {
    if (capacity == 0 || capacity > (std::size_t{1} << 30)) {
      throw UserError("ring buffer capacity must be in 1..2^30 records, got " +
                      std::to_string(capacity));
    }
    std::size_t size = 1;
    while (size < capacity) size <<= 1;
    mask_ = size - 1;
    slots_ = std::make_unique<T[]>(size);
  }
  SpscRing(const SpscRing&) = delete;
  SpscRing& operator=(const SpscRing&) = delete;

  std::size_t capacity() const { return mask_ + 1; }

  // Producer side. False (and nothing stored) when the ring is full.
  bool TryPush(const T& record) noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_cache_ > mask_) {
      tail_cache_ = tail_.load(std::memory_order_acquire);
      if (head - tail_cache_ > mask_) return false;
    }
    slots_[head & mask_] = record;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }

  // Consumer side. False when the ring is empty.
  bool TryPop(T* record) noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_cache_) {
      head_cache_ = head_.load(std::memory_order_acquire);
      if (tail == head_cache_) return false;
    }
    *record = slots_[tail & mask_];
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }

  // Consumer side: pops everything available and keeps only the newest record (a display that
  // samples the latest state). False when the ring was empty.
  bool PopLatest(T* record) noexcept {
    bool any = false;
    while (TryPop(record)) any = true;
    return any;
  }

  // Producer side: whether a TryPush would find room now (only the consumer can make room, so a
  // true answer stays true until the producer pushes).
  bool HasRoom() noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_cache_ > mask_) tail_cache_ = tail_.load(std::memory_order_acquire);
    return head - tail_cache_ <= mask_;
  }

  // Records waiting, as seen from either side (exact only when the other side is idle).
  std::size_t size() const noexcept {
    return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire);
  }

 private:
  // Producer and consumer fields on their own cache lines: no false sharing between the threads.
  alignas(64) std::atomic<std::size_t> head_{0};
  std::size_t tail_cache_ = 0;  // producer's last view of tail_
  alignas(64) std::atomic<std::size_t> tail_{0};
  std::size_t head_cache_ = 0;  // consumer's last view of head_
  alignas(64) std::size_t mask_ = 0;
  std::unique_ptr<T[]> slots_;
};

}  // namespace fitfeel
