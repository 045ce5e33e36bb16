#pragma once
/// @file
/// A scripted clock for executive tests: sleeping jumps to the deadline plus a per-cycle wake-up
/// lateness; compute time is charged explicitly with advance().

#include <cstdint>

#include "rig/rt/clock.h"

namespace rig::test {

class FakeClock final : public rt::Clock {
 public:
  std::int64_t now_ns() noexcept override { return now_; }
  void sleep_until(std::int64_t deadline) noexcept override {
    if (deadline > now_) now_ = deadline;
    now_ += next_wake_lateness_ns;
    next_wake_lateness_ns = 0;
  }
  std::int64_t realtime_ns() noexcept override { return now_; }
  void advance(std::int64_t ns) { now_ += ns; }
  std::int64_t next_wake_lateness_ns = 0;

 private:
  std::int64_t now_ = 1'000'000'000;
};

}  // namespace rig::test
