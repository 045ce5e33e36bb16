#include "rig/overrun_policy.h"

#include <array>
#include <cstdio>

namespace rig {
namespace {

constexpr std::array<std::string_view, 3> kKeys{"skip", "catch-up", "abort-after"};

}  // namespace

std::string_view overrun_policy_key(OverrunPolicy policy) noexcept {
  return kKeys[static_cast<std::size_t>(policy)];
}

std::optional<OverrunPolicy> overrun_policy_by_key(std::string_view key) noexcept {
  for (std::size_t i = 0; i < kKeys.size(); ++i) {
    if (kKeys[i] == key) return static_cast<OverrunPolicy>(i);
  }
  return std::nullopt;
}

std::string policy_name(OverrunPolicy policy, int abort_after) {
  if (policy == OverrunPolicy::kAbortAfter) return "abort-after=" + std::to_string(abort_after);
  return std::string(overrun_policy_key(policy));
}

OverrunDecision decide(const OverrunConfig& config, std::int64_t deadline_ns, std::int64_t end_ns,
                       std::int64_t period_ns, std::uint32_t consecutive_misses) noexcept {
  OverrunDecision d;
  d.next_deadline_ns = deadline_ns + period_ns;
  if (end_ns <= d.next_deadline_ns) return d;  // on time: the work ended by the next deadline
  d.consecutive_misses = consecutive_misses + 1;
  if (config.policy == OverrunPolicy::kCatchUp) {
    d.action = OverrunAction::kCatchUp;
    return d;
  }
  // The first period boundary after `end_ns`; the boundaries in between are skipped.
  const std::int64_t periods = (end_ns - deadline_ns) / period_ns + 1;
  d.next_deadline_ns = deadline_ns + periods * period_ns;
  d.skipped_periods = periods - 1;
  d.action =
      config.policy == OverrunPolicy::kAbortAfter && d.consecutive_misses >= config.abort_after
          ? OverrunAction::kAbort
          : OverrunAction::kSkip;
  return d;
}

void format_action(const OverrunDecision& decision, std::span<char> out) noexcept {
  if (out.empty()) return;
  switch (decision.action) {
    case OverrunAction::kNone:
      out[0] = '\0';
      return;
    case OverrunAction::kCatchUp:
      std::snprintf(out.data(), out.size(), "catch-up");
      return;
    case OverrunAction::kSkip:
      std::snprintf(out.data(), out.size(), "skip:%lld",
                    static_cast<long long>(decision.skipped_periods));
      return;
    case OverrunAction::kAbort:
      std::snprintf(out.data(), out.size(), "abort");
      return;
  }
}

}  // namespace rig
