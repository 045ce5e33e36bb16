#include "io/lcm/timing_window.h"

#include <gtest/gtest.h>

#include "io/lcm/snapshot_encoder.h"

namespace rig::io {
namespace {

TEST(TimingWindow, NearestRankPercentilesOfOneToThousand) {
  lcm::TimingWindow window;
  window.reset(1000);
  // Pushed in descending order so that the ring order differs from the sorted order.
  for (int i = 1000; i >= 1; --i) window.push(i, 2 * i, i % 100 == 0);
  const lcm::TimingPercentiles p = window.percentiles();
  EXPECT_EQ(p.cycles, 1000);
  EXPECT_EQ(p.misses, 10);
  EXPECT_EQ(p.lateness_p50_ns, 500);   // ceil(0.5 * 1000) = rank 500
  EXPECT_EQ(p.lateness_p99_ns, 990);   // rank 990
  EXPECT_EQ(p.lateness_p999_ns, 999);  // rank 999
  EXPECT_EQ(p.lateness_max_ns, 1000);
  EXPECT_EQ(p.compute_p50_ns, 1000);
  EXPECT_EQ(p.compute_p99_ns, 1980);
  EXPECT_EQ(p.compute_max_ns, 2000);
}

TEST(TimingWindow, KeepsOnlyTheLastCapacityCycles) {
  lcm::TimingWindow window;
  window.reset(10);
  for (int i = 1; i <= 15; ++i) window.push(i, 0, false);  // window holds 6..15
  const lcm::TimingPercentiles p = window.percentiles();
  EXPECT_EQ(p.cycles, 10);
  EXPECT_EQ(p.lateness_p50_ns, 10);  // rank 5 of 6..15
  EXPECT_EQ(p.lateness_max_ns, 15);
  EXPECT_EQ(p.lateness_p99_ns, 15);  // rank ceil(9.9) = 10
}

TEST(TimingWindow, EmptyWindowIsZero) {
  lcm::TimingWindow window;
  window.reset(5);
  EXPECT_EQ(window.percentiles().cycles, 0);
  EXPECT_EQ(window.percentiles().lateness_max_ns, 0);
}

TEST(RateDivider, DividesTheLoopRate) {
  lcm::RateDivider d;
  d.configure(1000.0, 0.001);
  EXPECT_EQ(d.divisor(), 1u);
  d.configure(10.0, 0.001);
  EXPECT_EQ(d.divisor(), 100u);
  EXPECT_TRUE(d.due(0));
  EXPECT_FALSE(d.due(99));
  EXPECT_TRUE(d.due(200));
  d.configure(300.0, 0.001);  // 3.33 cycles per message rounds to 3
  EXPECT_EQ(d.divisor(), 3u);
  d.configure(5000.0, 0.001);  // faster than the loop: every cycle
  EXPECT_EQ(d.divisor(), 1u);
  d.configure(0.0, 0.001);
  EXPECT_FALSE(d.enabled());
  EXPECT_FALSE(d.due(0));
}

}  // namespace
}  // namespace rig::io
