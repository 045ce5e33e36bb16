/// rig/overrun_policy: the decision of one cycle for concrete deadlines, ends and periods (no
/// clock, no thread).

#include "rig/overrun_policy.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

namespace rig {
namespace {

constexpr std::int64_t kPeriodNs = 1'000'000;        // 1 ms
constexpr std::int64_t kDeadlineNs = 5'000'000'000;  // the cycle aimed at t = 5 s

std::string action_of(const OverrunDecision& d) {
  std::array<char, 24> buf{};
  format_action(d, buf);
  return buf.data();
}

TEST(OverrunPolicy, OnTimeUpToTheNextDeadlineInclusive) {
  for (const OverrunPolicy policy :
       {OverrunPolicy::kSkip, OverrunPolicy::kCatchUp, OverrunPolicy::kAbortAfter}) {
    const OverrunConfig config{policy, 1};
    for (const std::int64_t end_ns :
         {kDeadlineNs, kDeadlineNs + 400'000, kDeadlineNs + kPeriodNs}) {
      const OverrunDecision d = decide(config, kDeadlineNs, end_ns, kPeriodNs, 7);
      EXPECT_FALSE(d.miss());
      EXPECT_EQ(d.action, OverrunAction::kNone);
      EXPECT_EQ(d.next_deadline_ns, kDeadlineNs + kPeriodNs);
      EXPECT_EQ(d.skipped_periods, 0);
      EXPECT_EQ(d.consecutive_misses, 0u);  // an on-time cycle ends the streak
      EXPECT_EQ(action_of(d), "");
    }
  }
}

TEST(OverrunPolicy, SkipJumpsToTheFirstBoundaryAfterTheEnd) {
  const OverrunConfig config{OverrunPolicy::kSkip, 10};
  // Work ends 3.5 ms after the deadline: boundaries +1, +2, +3 ms have passed; next is +4 ms.
  OverrunDecision d = decide(config, kDeadlineNs, kDeadlineNs + 3'500'000, kPeriodNs, 0);
  EXPECT_EQ(d.action, OverrunAction::kSkip);
  EXPECT_EQ(d.next_deadline_ns, kDeadlineNs + 4 * kPeriodNs);
  EXPECT_EQ(d.skipped_periods, 3);
  EXPECT_EQ(d.consecutive_misses, 1u);
  EXPECT_EQ(action_of(d), "skip:3");
  // 1 ns after the next deadline: that boundary is skipped, the one after is next.
  d = decide(config, kDeadlineNs, kDeadlineNs + kPeriodNs + 1, kPeriodNs, 2);
  EXPECT_EQ(d.next_deadline_ns, kDeadlineNs + 2 * kPeriodNs);
  EXPECT_EQ(d.skipped_periods, 1);
  EXPECT_EQ(d.consecutive_misses, 3u);
  EXPECT_EQ(action_of(d), "skip:1");
  // Ending exactly on a boundary: it is not after the end, so it is skipped too.
  d = decide(config, kDeadlineNs, kDeadlineNs + 2 * kPeriodNs, kPeriodNs, 0);
  EXPECT_EQ(d.next_deadline_ns, kDeadlineNs + 3 * kPeriodNs);
  EXPECT_EQ(d.skipped_periods, 2);
}

TEST(OverrunPolicy, SkipOverManyMissedPeriods) {
  const OverrunConfig config{OverrunPolicy::kSkip, 10};
  // A 2.5 s stall at a 1 ms period: 2500 boundaries passed.
  const OverrunDecision d =
      decide(config, kDeadlineNs, kDeadlineNs + 2'500'000'000 + 250'000, kPeriodNs, 0);
  EXPECT_EQ(d.skipped_periods, 2500);
  EXPECT_EQ(d.next_deadline_ns, kDeadlineNs + 2501 * kPeriodNs);
  EXPECT_EQ(action_of(d), "skip:2500");
  // A 250 us period, 1 s late: 4000 boundaries passed.
  const OverrunDecision fast = decide(config, 1'000, 1'000 + 1'000'000'000 + 1, 250'000, 0);
  EXPECT_EQ(fast.skipped_periods, 4000);
  EXPECT_EQ(fast.next_deadline_ns, 1'000 + 4001 * 250'000);
}

TEST(OverrunPolicy, CatchUpKeepsTheGridAndSkipsNothing) {
  const OverrunConfig config{OverrunPolicy::kCatchUp, 10};
  const OverrunDecision d = decide(config, kDeadlineNs, kDeadlineNs + 3'500'000, kPeriodNs, 4);
  EXPECT_EQ(d.action, OverrunAction::kCatchUp);
  EXPECT_EQ(d.next_deadline_ns, kDeadlineNs + kPeriodNs);  // already past: runs at once
  EXPECT_EQ(d.skipped_periods, 0);
  EXPECT_EQ(d.consecutive_misses, 5u);
  EXPECT_EQ(action_of(d), "catch-up");
  // Many periods late: still one period on, nothing skipped.
  const OverrunDecision late =
      decide(config, kDeadlineNs, kDeadlineNs + 900 * kPeriodNs, kPeriodNs, 0);
  EXPECT_EQ(late.next_deadline_ns, kDeadlineNs + kPeriodNs);
  EXPECT_EQ(late.skipped_periods, 0);
}

TEST(OverrunPolicy, AbortAfterFiresAtExactlyNConsecutiveMisses) {
  const OverrunConfig config{OverrunPolicy::kAbortAfter, 3};
  std::uint32_t consecutive = 0;
  std::int64_t deadline_ns = kDeadlineNs;
  std::array<OverrunAction, 3> actions{};
  for (int k = 0; k < 3; ++k) {  // each cycle's work takes 1.5 ms
    const OverrunDecision d =
        decide(config, deadline_ns, deadline_ns + 1'500'000, kPeriodNs, consecutive);
    actions[static_cast<std::size_t>(k)] = d.action;
    EXPECT_EQ(d.skipped_periods, 1);  // as skip, also when it fires
    EXPECT_EQ(d.next_deadline_ns, deadline_ns + 2 * kPeriodNs);
    consecutive = d.consecutive_misses;
    deadline_ns = d.next_deadline_ns;
  }
  EXPECT_EQ(actions[0], OverrunAction::kSkip);
  EXPECT_EQ(actions[1], OverrunAction::kSkip);
  EXPECT_EQ(actions[2], OverrunAction::kAbort);
  EXPECT_EQ(consecutive, 3u);
  const OverrunDecision fired = decide(config, kDeadlineNs, kDeadlineNs + 1'500'000, kPeriodNs, 2);
  EXPECT_EQ(action_of(fired), "abort");
  // An on-time cycle in between resets the count: two misses, on time, two misses: no abort.
  EXPECT_EQ(decide(config, kDeadlineNs, kDeadlineNs + 1'500'000, kPeriodNs, 1).action,
            OverrunAction::kSkip);
  EXPECT_EQ(decide(config, kDeadlineNs, kDeadlineNs + 10, kPeriodNs, 2).consecutive_misses, 0u);
  // N = 1: the first miss aborts.
  EXPECT_EQ(
      decide({OverrunPolicy::kAbortAfter, 1}, kDeadlineNs, kDeadlineNs + 1'500'000, kPeriodNs, 0)
          .action,
      OverrunAction::kAbort);
}

TEST(OverrunPolicy, NamesAndKeys) {
  EXPECT_EQ(policy_name(OverrunPolicy::kSkip, 10), "skip");
  EXPECT_EQ(policy_name(OverrunPolicy::kCatchUp, 10), "catch-up");
  EXPECT_EQ(policy_name(OverrunPolicy::kAbortAfter, 7), "abort-after=7");
  for (const OverrunPolicy p :
       {OverrunPolicy::kSkip, OverrunPolicy::kCatchUp, OverrunPolicy::kAbortAfter}) {
    EXPECT_EQ(overrun_policy_by_key(overrun_policy_key(p)), p);
  }
  EXPECT_EQ(overrun_policy_key(OverrunPolicy::kAbortAfter), "abort-after");
  EXPECT_FALSE(overrun_policy_by_key("sometimes").has_value());
}

}  // namespace
}  // namespace rig
