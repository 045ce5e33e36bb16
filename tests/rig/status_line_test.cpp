// The console status line (rig/status_line.h): its text with and without CAN, the compact
// counts, and its width on a 120-column terminal ("rig: " included) for long bench runs.
#include "rig/status_line.h"

#include <gtest/gtest.h>

namespace rig {
namespace {

constexpr std::size_t kTerminalColumns = 120;
constexpr std::size_t kPrefix = 5;  // "rig: "

StatusFigures timing(std::uint64_t cycles, std::uint64_t misses) {
  StatusFigures f;
  f.cycles = cycles;
  f.misses = misses;
  f.sim_time_s = static_cast<double>(cycles) * 1e-3;
  f.lateness_p50_ns = 25'000;
  f.lateness_p99_ns = 75'300;
  f.lateness_p999_ns = 303'000;
  f.lateness_max_ns = 1'234'000;
  f.compute_p50_ns = 4'700;
  f.compute_p99_ns = 6'100;
  f.compute_max_ns = 9'900;
  return f;
}

TEST(CompactCount, ExactBelowTenThousandThenThreeSignificantDigitsRoundedDown) {
  EXPECT_EQ(compact_count(0), "0");
  EXPECT_EQ(compact_count(9999), "9999");
  EXPECT_EQ(compact_count(10000), "10.0k");
  EXPECT_EQ(compact_count(12399), "12.3k");
  EXPECT_EQ(compact_count(999'999), "999k");
  EXPECT_EQ(compact_count(1'999'999), "1.99M");
  EXPECT_EQ(compact_count(86'400'000), "86.4M");
  EXPECT_EQ(compact_count(604'800'000), "604M");
  EXPECT_EQ(compact_count(1'814'400'000), "1.81G");
  EXPECT_EQ(compact_count(UINT64_MAX), "18.4E");
  for (std::uint64_t n = 1; n < UINT64_MAX / 7; n = n * 7 + 3) {
    EXPECT_LE(compact_count(n).size(), 5U) << n;
  }
}

TEST(StatusLine, WithoutCanIsTheTimingLineAsBefore) {
  EXPECT_EQ(status_line(timing(12000, 3)),
            "cycles 12000, misses 3, sim 12.000 s, lateness p50/p99/p99.9/max "
            "25.0/75.3/303.0/1234.0 us, compute p50/p99/max 4.7/6.1/9.9 us");
}

TEST(StatusLine, WithCanShowsTheCountersAndEndsInTheBusState) {
  StatusFigures f = timing(86'400'000, 3);
  f.can.bus_state = io::BusState::kUp;
  f.can.frames_received = 8'640'000;
  f.can.frames_sent = 25'920'000;
  f.can.timeouts = 2;
  f.can.counter_failures = 4;
  f.can.checksum_failures = 1;
  f.can.out_of_range = 7;
  EXPECT_EQ(status_line(f),
            "cycles 86.4M, misses 3, late max 1234 us, rx 8.64M tx 25.9M to 2 rej 5 oor 7, CAN up");
  for (const auto s : {io::BusState::kErrorPassive, io::BusState::kBusOff, io::BusState::kDown}) {
    f.can.bus_state = s;
    const std::string line = status_line(f);
    EXPECT_TRUE(line.ends_with(std::string(", CAN ") + io::bus_state_name(s))) << line;
  }
}

// Every count at its widest (5 characters) and the longest bus state: still 120 columns.
TEST(StatusLine, TheWidestCanLineFitsA120ColumnTerminal) {
  StatusFigures f = timing(604'800'000, 12'345);
  f.lateness_max_ns = 98'765'000;
  f.can.bus_state = io::BusState::kErrorPassive;
  f.can.frames_received = 60'480'000'000;
  f.can.frames_sent = 18'144'000'000;
  f.can.timeouts = 12'345;
  f.can.counter_failures = 23'456;
  f.can.checksum_failures = 34'567;
  f.can.out_of_range = 45'678;
  const std::string line = status_line(f);
  EXPECT_EQ(line,
            "cycles 604M, misses 12.3k, late max 98.7k us, rx 60.4G tx 18.1G to 12.3k rej 58.0k "
            "oor 45.6k, CAN error-passive");
  EXPECT_LE(kPrefix + line.size(), kTerminalColumns) << line;
  // 604M is 4 characters: with 5 everywhere the line is at its widest.
  f.cycles = 60'480'000'000;
  EXPECT_LE(kPrefix + status_line(f).size(), kTerminalColumns);
}

}  // namespace
}  // namespace rig
