#pragma once
/// @file
/// What passes from the loop thread to the dispatcher: a lock-free ring of snapshots, the count
/// of those dropped, and the end of the run.
///
/// Real time: the loop never waits and never signals per cycle (a full ring drops the snapshot
/// and counts it); the dispatcher looks every poll interval and is woken at the end. Offline:
/// back-pressure instead of drops (every sink sees every cycle, so runs are deterministic), and
/// the two sides hand over in half-ring batches: the dispatcher sleeps until half a ring is
/// filled, a loop that finds the ring full sleeps until half of it is free. Neither sleeps a
/// fixed time, and a hand-over costs one futex wake per half ring, not per cycle.

#include <atomic>
#include <cstddef>
#include <cstdint>

#include "io/snapshot.h"
#include "rig/rt/event_count.h"
#include "rig/rt/spsc_ring.h"

namespace rig {

class SnapshotHandoff {
 public:
  /// Allocates the ring here, once.
  SnapshotHandoff(std::size_t capacity, bool offline);

  // ---- loop thread ----
  /// The slot to fill, or nullptr (counted as dropped): in real time when the ring is full;
  /// offline only when `stop` was set while it waited for the dispatcher.
  io::Snapshot* claim(const std::atomic<bool>& stop) noexcept {
    io::Snapshot* slot = ring_.claim();
    return slot != nullptr ? slot : claim_full(stop);
  }
  /// Publishes the claimed slot; offline, wakes the dispatcher once half a ring is waiting.
  void commit() noexcept {
    ring_.commit();
    if (offline_ && ring_.size() >= wake_dispatcher_at_) filled_.notify();
  }
  /// The loop has stopped: nothing more comes. Wakes the dispatcher.
  void close() noexcept;
  /// Wakes a claim() waiting offline so that it sees `stop` (async-signal-safe).
  void interrupt() noexcept { freed_.notify(); }

  // ---- dispatcher ----
  [[nodiscard]] const io::Snapshot* front() const noexcept { return ring_.front(); }
  /// Frees the front slot; offline, wakes a waiting loop once half the ring is free.
  void release() noexcept;
  /// Sleeps until there is work: offline half a ring, in real time at most `poll_ns`; at once
  /// when the loop has closed.
  void wait_for_work(std::int64_t poll_ns) noexcept;
  [[nodiscard]] bool closed() const noexcept { return closed_.load(std::memory_order_acquire); }
  [[nodiscard]] std::uint64_t dropped() const noexcept {
    return dropped_.load(std::memory_order_relaxed);
  }

 private:
  /// The ring was full: offline, wait for the dispatcher; in real time, drop (counted).
  io::Snapshot* claim_full(const std::atomic<bool>& stop) noexcept;

  rt::SpscRing<io::Snapshot> ring_;
  const bool offline_;
  const std::size_t wake_dispatcher_at_;  ///< offline: fill level that wakes the dispatcher
  const std::size_t wake_loop_at_;        ///< offline: fill level that wakes a waiting loop
  std::atomic<std::uint64_t> dropped_{0};
  std::atomic<bool> closed_{false};
  rt::EventCount filled_;  ///< the dispatcher waits here
  rt::EventCount freed_;   ///< an offline loop waits here
};

}  // namespace rig
