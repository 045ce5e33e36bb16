#pragma once
/// @file
/// Times the phases of one cycle by name: end(phase) charges the phase with the time since the
/// previous mark (the first mark is the wake-up) and returns the time read.

#include <cstdint>

#include "io/snapshot.h"
#include "rig/rt/clock.h"

namespace rig {

class PhaseTimer {
 public:
  PhaseTimer(rt::Clock& clock, io::CycleTiming& timing) noexcept
      : clock_(clock), timing_(timing), mark_ns_(timing.wake_ns) {}

  std::int64_t end(io::Phase phase) noexcept {
    const std::int64_t now_ns = clock_.now_ns();
    timing_.phase_ns[io::index(phase)] = now_ns - mark_ns_;
    mark_ns_ = now_ns;
    return now_ns;
  }

 private:
  rt::Clock& clock_;
  io::CycleTiming& timing_;
  std::int64_t mark_ns_;
};

}  // namespace rig
