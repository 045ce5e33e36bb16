#pragma once
/// @file
/// The executive's notion of time, injectable: the real CLOCK_MONOTONIC with clock_nanosleep,
/// a virtual clock for --offline runs, and fake clocks in tests.

#include <cstdint>

namespace rig::rt {

class Clock {
 public:
  Clock() = default;
  Clock(const Clock&) = delete;
  Clock& operator=(const Clock&) = delete;
  virtual ~Clock() = default;
  /// Monotonic time [ns].
  virtual std::int64_t now_ns() noexcept = 0;
  /// Blocks until now_ns() >= deadline_ns (returns at once if it already is).
  virtual void sleep_until(std::int64_t deadline_ns) noexcept = 0;
  /// Wall-clock (CLOCK_REALTIME) time [ns since the epoch], for log lines only.
  virtual std::int64_t realtime_ns() noexcept = 0;
};

/// CLOCK_MONOTONIC and absolute clock_nanosleep (EINTR-safe).
class MonotonicClock final : public Clock {
 public:
  std::int64_t now_ns() noexcept override;
  void sleep_until(std::int64_t deadline_ns) noexcept override;
  std::int64_t realtime_ns() noexcept override;
};

/// --offline: time is virtual and jumps to each deadline; nothing sleeps, so runs are
/// deterministic. Reported lateness and compute are 0.
class VirtualClock final : public Clock {
 public:
  std::int64_t now_ns() noexcept override { return now_ns_; }
  void sleep_until(std::int64_t deadline_ns) noexcept override {
    if (deadline_ns > now_ns_) now_ns_ = deadline_ns;
  }
  std::int64_t realtime_ns() noexcept override { return now_ns_; }

 private:
  std::int64_t now_ns_ = 0;
};

}  // namespace rig::rt
