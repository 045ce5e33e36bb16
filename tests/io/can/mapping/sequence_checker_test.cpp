// The receive-side alive-counter check (io/can/mapping/sequence_checker.h) and the report rate
// limit (report_limiter.h).
#include "io/can/mapping/sequence_checker.h"

#include <gtest/gtest.h>

#include <vector>

#include "io/can/mapping/report_limiter.h"

namespace rig::io::can::mapping {
namespace {

using R = SequenceResult;

std::vector<R> feed(SequenceChecker& c, const std::vector<std::uint32_t>& values) {
  std::vector<R> out;
  for (std::uint32_t v : values) out.push_back(c.check(v));
  return out;
}

TEST(SequenceChecker, ProperStepsWrapAtTheModulus) {
  SequenceChecker c(SequenceParams{.modulus = 16, .max_delta = 1, .good_steps_to_unlatch = 1});
  EXPECT_EQ(feed(c, {14, 15, 0, 1}), (std::vector<R>{R::kOk, R::kOk, R::kOk, R::kOk}));
  EXPECT_FALSE(c.latched());
}

TEST(SequenceChecker, FrozenCounterStaysRejectedForever) {
  SequenceChecker c(SequenceParams{.modulus = 16, .max_delta = 1, .good_steps_to_unlatch = 1});
  EXPECT_EQ(c.check(7), R::kOk);  // the first value of a sequence
  for (int i = 0; i < 1000; ++i) {
    // kRepeated; kLatched for the first value after a restart (nothing to step from)
    ASSERT_FALSE(accepted(c.check(7)));
    if (i % 3 == 2) c.restart();  // a message timeout in between does not end the latch
    ASSERT_TRUE(c.latched());
  }
  // Moving properly again: the resynchronising value, then one proper step.
  EXPECT_EQ(c.check(8), R::kOk);
  EXPECT_FALSE(c.latched());
}

TEST(SequenceChecker, RestartWhileLatchedNeedsAProperStep) {
  SequenceChecker c(SequenceParams{.modulus = 16, .max_delta = 1, .good_steps_to_unlatch = 1});
  EXPECT_EQ(feed(c, {3, 3}), (std::vector<R>{R::kOk, R::kRepeated}));
  c.restart();
  EXPECT_EQ(c.check(3), R::kRepeated);  // still the value from before the silence
  c.restart();
  EXPECT_EQ(c.check(9), R::kLatched);  // a jump after a restart is no skip, but no proper step
  EXPECT_EQ(c.check(10), R::kOk);
  c.restart();
  EXPECT_EQ(c.check(2), R::kOk);  // not latched: a sender may resume anywhere after a timeout
  c.reset();                      // a new run forgets the latch
  EXPECT_EQ(c.check(4), R::kOk);
}

TEST(SequenceChecker, SkipsBeyondMaxDeltaLatchUntilGoodSteps) {
  SequenceChecker c(SequenceParams{.modulus = 256, .max_delta = 2, .good_steps_to_unlatch = 3});
  EXPECT_EQ(feed(c, {10, 12, 13}), (std::vector<R>{R::kOk, R::kOk, R::kOk}));  // steps 2, 1
  EXPECT_EQ(c.check(16), R::kSkipped);                                         // step 3
  // Three proper steps in a row end the latch; the third frame is the first accepted.
  EXPECT_EQ(feed(c, {17, 18, 19, 20}), (std::vector<R>{R::kLatched, R::kLatched, R::kOk, R::kOk}));
  // A failure during the recovery starts it again.
  EXPECT_EQ(feed(c, {20, 21, 22, 22, 23, 24, 25}),
            (std::vector<R>{R::kRepeated, R::kLatched, R::kLatched, R::kRepeated, R::kLatched,
                            R::kLatched, R::kOk}));
}

TEST(SequenceChecker, ProperStepsAcrossARestartCountTowardsTheUnlatch) {
  SequenceChecker c(SequenceParams{.modulus = 16, .max_delta = 1, .good_steps_to_unlatch = 3});
  EXPECT_EQ(feed(c, {0, 1, 5, 6, 7}),
            (std::vector<R>{R::kOk, R::kOk, R::kSkipped, R::kLatched, R::kLatched}));
  c.restart();  // the message timed out while latched (rejected frames do not refresh it)
  EXPECT_EQ(c.check(8), R::kOk);  // the third proper step
}

TEST(SequenceChecker, AFrozenCounterSlowerThanTheTimeoutIsStillRepeated) {
  // Frames further apart than the message timeout: every frame follows a restart.
  SequenceChecker c(SequenceParams{});
  EXPECT_EQ(c.check(1), R::kOk);
  for (int i = 0; i < 50; ++i) {
    c.restart();
    ASSERT_EQ(c.check(1), R::kRepeated);
  }
}

TEST(SequenceChecker, ValuesBeyondTheModulusAreInvalid) {
  SequenceChecker c(SequenceParams{.modulus = 15, .max_delta = 1, .good_steps_to_unlatch = 1});
  EXPECT_EQ(c.check(15), R::kInvalid);  // e.g. 0xF as "not available" in a 4-bit field
  EXPECT_TRUE(c.latched());
  EXPECT_EQ(feed(c, {0, 1}), (std::vector<R>{R::kLatched, R::kOk}));
}

TEST(SequenceChecker, OneInFourStaysRejectedUnderAFrozenCounterWithTimeouts) {
  // The symptom: with the latch cleared on every timeout, 1 frame in 4 got through.
  SequenceChecker c(SequenceParams{});
  int accepted_frames = 0;
  EXPECT_EQ(feed(c, {5, 5}), (std::vector<R>{R::kOk, R::kRepeated}));
  for (int i = 0; i < 400; ++i) {
    if (i % 4 == 0) c.restart();
    accepted_frames += accepted(c.check(5)) ? 1 : 0;
  }
  EXPECT_EQ(accepted_frames, 0);
}

TEST(ReportLimiter, FirstAtOnceThenOnePerIntervalWithTheCount) {
  ReportLimiter l(1'000'000'000);
  EXPECT_EQ(l.take_due(0), 0u);
  l.count();
  EXPECT_EQ(l.take_due(5), 1u);  // the first: at once
  for (int i = 0; i < 99; ++i) l.count();
  EXPECT_EQ(l.take_due(500'000'000), 0u);  // within the second
  EXPECT_EQ(l.pending(), 99u);
  EXPECT_EQ(l.take_due(1'000'000'005), 99u);
  l.count();
  EXPECT_EQ(l.take_due(1'500'000'000), 0u);
  EXPECT_EQ(l.take_due(2'000'000'004), 0u);
  EXPECT_EQ(l.take_due(2'000'000'005), 1u);
  EXPECT_EQ(l.take_due(9'000'000'000), 0u);  // nothing pending: nothing to say
}

}  // namespace
}  // namespace rig::io::can::mapping
