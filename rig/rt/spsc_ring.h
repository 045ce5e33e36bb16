#pragma once
/// @file
/// A bounded lock-free single-producer single-consumer ring. The producer (the RT loop) fills a
/// slot in place and commits it; the consumer reads the front slot in place and releases it. No
/// allocation after construction, no locks, no blocking. Depends on nothing of the project.

#include <atomic>
#include <cstddef>
#include <memory>

namespace rig::rt {

template <typename T>
class SpscRing {
 public:
  /// Allocates `capacity` slots here, once.
  explicit SpscRing(std::size_t capacity) : capacity_(capacity), slots_(new T[capacity]()) {}

  /// Producer: the slot to fill next, or nullptr if the ring is full.
  T* claim() noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_.load(std::memory_order_acquire) >= capacity_) return nullptr;
    return &slots_[head % capacity_];
  }
  /// Producer: publishes the slot returned by the last claim().
  void commit() noexcept {
    head_.store(head_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
  }
  /// Producer: copies `value` in; false (and nothing written) if full.
  bool push(const T& value) noexcept {
    T* slot = claim();
    if (slot == nullptr) return false;
    *slot = value;
    commit();
    return true;
  }

  /// Consumer: the oldest committed slot, or nullptr if empty.
  const T* front() const noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (head_.load(std::memory_order_acquire) == tail) return nullptr;
    return &slots_[tail % capacity_];
  }
  /// Consumer: frees the slot returned by front().
  void release() noexcept {
    tail_.store(tail_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
  }

  /// Either side: committed slots not yet released (exact on the caller's side, at most stale
  /// towards the other side's progress).
  [[nodiscard]] std::size_t size() const noexcept {
    return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire);
  }
  [[nodiscard]] std::size_t capacity() const noexcept { return capacity_; }

 private:
  const std::size_t capacity_;
  std::unique_ptr<T[]> slots_;
  alignas(64) std::atomic<std::size_t> head_{0};
  alignas(64) std::atomic<std::size_t> tail_{0};
};

}  // namespace rig::rt
