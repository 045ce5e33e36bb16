#include "rig/snapshot_handoff.h"

#include <algorithm>

namespace rig {
namespace {

/// A safety net only: every state change the other side waits for is signalled.
constexpr std::int64_t kOfflineWaitNs = 1'000'000'000;

}  // namespace

SnapshotHandoff::SnapshotHandoff(std::size_t capacity, bool offline)
    : ring_(capacity),
      offline_(offline),
      wake_dispatcher_at_(std::max<std::size_t>(1, capacity / 2)),
      wake_loop_at_(std::min(capacity - 1, capacity / 2)) {}

io::Snapshot* SnapshotHandoff::claim_full(const std::atomic<bool>& stop) noexcept {
  io::Snapshot* slot = nullptr;
  while (offline_ && (slot = ring_.claim()) == nullptr && !stop.load(std::memory_order_relaxed)) {
    const std::uint32_t key = freed_.prepare_wait();
    if (ring_.size() <= wake_loop_at_ || stop.load(std::memory_order_relaxed)) {
      freed_.cancel_wait();
    } else {
      freed_.wait(key, kOfflineWaitNs);
    }
  }
  if (slot == nullptr) dropped_.fetch_add(1, std::memory_order_relaxed);
  return slot;
}

void SnapshotHandoff::close() noexcept {
  closed_.store(true, std::memory_order_release);
  filled_.notify();
}

void SnapshotHandoff::release() noexcept {
  ring_.release();
  if (offline_ && ring_.size() <= wake_loop_at_) freed_.notify();
}

void SnapshotHandoff::wait_for_work(std::int64_t poll_ns) noexcept {
  const std::uint32_t key = filled_.prepare_wait();
  if (closed() || (offline_ && ring_.size() >= wake_dispatcher_at_)) {
    filled_.cancel_wait();
    return;
  }
  filled_.wait(key, offline_ ? kOfflineWaitNs : poll_ns);
}

}  // namespace rig
