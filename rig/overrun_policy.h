#pragma once
/// @file
/// What the loop does after a cycle whose work ended after the next deadline: the policy, its
/// names, and one pure decision per cycle (no clock, no thread: unit-tested with numbers).
///
///   skip         the next deadline is the first period boundary after the end of the work; the
///                periods in between are skipped (simulated time falls behind, no burst).
///   catch-up     the next deadline stays one period on; the late steps run back to back.
///   abort-after  as skip, and the run stops at N consecutive misses.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace rig {

enum class OverrunPolicy : std::uint8_t { kSkip, kCatchUp, kAbortAfter };

/// The values of [rig] overrun_policy: "skip", "catch-up", "abort-after".
std::string_view overrun_policy_key(OverrunPolicy policy) noexcept;
std::optional<OverrunPolicy> overrun_policy_by_key(std::string_view key) noexcept;
/// The run's policy as logged and summarised: "skip", "catch-up" or "abort-after=N".
std::string policy_name(OverrunPolicy policy, int abort_after);

struct OverrunConfig {
  OverrunPolicy policy = OverrunPolicy::kSkip;
  std::uint32_t abort_after = 10;  ///< consecutive misses that stop the run (kAbortAfter)
};

enum class OverrunAction : std::uint8_t { kNone, kCatchUp, kSkip, kAbort };

struct OverrunDecision {
  std::int64_t next_deadline_ns = 0;
  std::int64_t skipped_periods = 0;  ///< deadlines passed over (skip, and abort as it fires)
  OverrunAction action = OverrunAction::kNone;  ///< kNone: the cycle was on time
  std::uint32_t consecutive_misses = 0;         ///< including this cycle; 0 if on time
  [[nodiscard]] bool miss() const noexcept { return action != OverrunAction::kNone; }
};

/// The cycle aimed at `deadline_ns` and its work ended at `end_ns`; it missed if that is after
/// the next deadline (`deadline_ns + period_ns`). `consecutive_misses` counts the misses right
/// before this cycle.
OverrunDecision decide(const OverrunConfig& config, std::int64_t deadline_ns, std::int64_t end_ns,
                       std::int64_t period_ns, std::uint32_t consecutive_misses) noexcept;

/// The action as the overrun log writes it: "catch-up", "skip:K" or "abort" ("" if on time).
/// Writes a terminated string into `out`; no allocation.
void format_action(const OverrunDecision& decision, std::span<char> out) noexcept;

}  // namespace rig
