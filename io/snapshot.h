#pragma once
/// @file
/// What the RT loop hands to the non-RT threads each cycle, by value through a lock-free ring.

#include <array>
#include <cstdint>

#include "io/io_counters.h"
#include "model/report.h"
#include "model/signals.h"

namespace rig::io {

/// Phases of one cycle, in order.
enum class Phase : std::uint8_t { kInputs, kDriver, kModel, kOutputs, kHandoff, kCount };
inline constexpr std::size_t kPhaseCount = static_cast<std::size_t>(Phase::kCount);
constexpr std::size_t index(Phase p) { return static_cast<std::size_t>(p); }
/// The phases' names in logs and the summary ("phase_ns": {"inputs": ...}).
inline constexpr std::array<const char*, kPhaseCount> kPhaseNames{"inputs", "driver", "model",
                                                                  "outputs", "handoff"};

/// Timing of one cycle, measured on CLOCK_MONOTONIC.
struct CycleTiming {
  std::uint64_t cycle = 0;
  double sim_time_s = 0;
  std::int64_t deadline_ns = 0;  ///< the absolute wake-up time this cycle aimed at
  std::int64_t wake_ns = 0;      ///< when it actually woke
  std::int64_t lateness_ns = 0;  ///< wake_ns - deadline_ns
  std::array<std::int64_t, kPhaseCount> phase_ns{};
  std::int64_t compute_ns = 0;  ///< sum of the phases (wake-up to the end of the handoff)
  bool deadline_miss = false;   ///< work ended after the next deadline (rig/overrun_policy)
  std::uint32_t consecutive_misses = 0;
};

/// One cycle as the tools see it.
struct Snapshot {
  CycleTiming timing{};
  model::Signals signals{};
  model::ModelReport report{};
  IoCounters can{};
};

}  // namespace rig::io
