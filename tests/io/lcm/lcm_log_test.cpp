#include <lcm/eventlog.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/lcm/lcm_log_writer.h"
#include "rig/log2csv/log_to_csv.h"
#include "rig/vehicle_state_t.hpp"
#include "tests/io/lcm/synthetic_snapshot.h"

namespace rig::io {
namespace {

constexpr double kPeriod = 0.001;

std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
}

/// Writes `cycles` synthetic snapshots through the log writer.
void write_log(const std::filesystem::path& file, std::uint64_t cycles) {
  lcm::LcmLogWriter writer(file.string(), lcm::LcmSettings{});
  RunInfo info;
  info.period_s = kPeriod;
  writer.start(info);
  for (std::uint64_t c = 0; c < cycles; ++c) {
    writer.consume(test::make_synthetic_snapshot(c, kPeriod), 0);
  }
  writer.stop();
  EXPECT_EQ(writer.events_written(), cycles + cycles / 10 + cycles / 100);
}

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  [[nodiscard]] std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return i;
    }
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  [[nodiscard]] double number(std::size_t row, const std::string& name) const {
    return std::stod(rows.at(row).at(column(name)));
  }
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

Table read_csv(const std::filesystem::path& file) {
  Table t;
  std::ifstream in(file);
  std::string line;
  EXPECT_TRUE(std::getline(in, line)) << file;
  t.header = split(line);
  while (std::getline(in, line)) t.rows.push_back(split(line));
  return t;
}

TEST(LcmLogWriter, WritesAnEventLogThatLcmReadsBack) {
  const auto file = temp_path("rig_lcm_writer.lcm");
  write_log(file, 1000);

  lcm_eventlog_t* log = lcm_eventlog_create(file.c_str(), "r");
  ASSERT_NE(log, nullptr);
  std::map<std::string, int> counts;
  std::int64_t first_state_us = -1, last_state_us = -1;
  rig::vehicle_state_t last{};
  while (lcm_eventlog_event_t* e = lcm_eventlog_read_next_event(log)) {
    const std::string channel(e->channel, static_cast<std::size_t>(e->channellen));
    ++counts[channel];
    if (channel == "RIG_STATE") {
      if (first_state_us < 0) first_state_us = e->timestamp;
      last_state_us = e->timestamp;
      EXPECT_GE(last.decode(e->data, 0, e->datalen), 0);
    }
    lcm_eventlog_free_event(e);
  }
  lcm_eventlog_destroy(log);
  EXPECT_EQ(counts["RIG_STATE"], 1000);
  EXPECT_EQ(counts["RIG_SIGNALS"], 100);
  EXPECT_EQ(counts["RIG_STATUS"], 10);
  // Timestamps follow simulated time: 999 periods of 1000 us between first and last state.
  EXPECT_EQ(last_state_us - first_state_us, 999'000);
  EXPECT_EQ(last.cycle, 999);
  EXPECT_DOUBLE_EQ(last.wheel_spin_radps[5], 30.0 + 9.99 + 11.0);
  std::filesystem::remove(file);
}

TEST(LcmLogWriter, UnwritablePathThrows) {
  EXPECT_THROW(lcm::LcmLogWriter("/nonexistent-dir/x.lcm", lcm::LcmSettings{}), std::runtime_error);
}

// /dev/full fails every write with ENOSPC (a full disk): nothing is written, every event that
// did not reach the file is counted (also those only flushed at stop()), none silently.
TEST(LcmLogWriter, WriteFailuresOnAFullDiskAreCounted) {
  lcm::LcmLogWriter writer("/dev/full", lcm::LcmSettings{});
  RunInfo info;
  info.period_s = kPeriod;
  writer.start(info);
  for (std::uint64_t c = 0; c < 100; ++c)
    writer.consume(test::make_synthetic_snapshot(c, kPeriod), 0);
  writer.stop();
  const WriteFailures f = writer.write_failures();
  EXPECT_GT(f.count, 0u);
  EXPECT_EQ(f.what, "LCM log /dev/full: No space left on device");
  EXPECT_LT(writer.events_written(), 100u + 10u + 1u);  // not all of them reached the file
}

TEST(LcmLogWriter, EarlierLogIsKeptAsDotOne) {
  const auto file = temp_path("rig_lcm_rotate.lcm");
  std::filesystem::remove(file);
  std::filesystem::remove(file.string() + ".1");
  write_log(file, 100);
  const auto first_size = std::filesystem::file_size(file);
  write_log(file, 200);
  EXPECT_EQ(std::filesystem::file_size(file.string() + ".1"), first_size);
  EXPECT_GT(std::filesystem::file_size(file), first_size);
  std::filesystem::remove(file);
  std::filesystem::remove(file.string() + ".1");
}

TEST(Log2Csv, ReproducesKnownValuesAndFlattensArrays) {
  const auto file = temp_path("rig_lcm_log2csv.lcm");
  const auto dir = temp_path("rig_lcm_log2csv_out");
  write_log(file, 300);
  {
    // An event of a type the rig does not know: it gets timestamp, channel and size.
    lcm_eventlog_t* log = lcm_eventlog_create(file.c_str(), "a");
    ASSERT_NE(log, nullptr);
    char channel[] = "OTHER/TOOL";
    std::uint8_t data[5] = {1, 2, 3, 4, 5};
    lcm_eventlog_event_t e{0, 42, 10, 5, channel, data};
    ASSERT_EQ(lcm_eventlog_write_event(log, &e), 0);
    lcm_eventlog_destroy(log);
  }
  const auto summary = log2csv::convert_lcm_log(file, dir);
  EXPECT_EQ(summary.events, 300u + 30u + 3u + 1u);
  EXPECT_EQ(summary.channels.at("RIG_STATE").rows, 300u);
  EXPECT_EQ(summary.channels.at("RIG_SIGNALS").rows, 30u);
  EXPECT_EQ(summary.channels.at("RIG_STATUS").rows, 3u);

  const Table state = read_csv(dir / "RIG_STATE.csv");
  ASSERT_EQ(state.rows.size(), 300u);
  EXPECT_EQ(state.header.front(), "timestamp_us");
  // 8 leading scalars, 2 units x (15 + the 3 frame-torsion fields of issue 17), num_wheels,
  // 6 x (1 + 24 + 1 flag: 17 + the 5 road fields of issue 16 + the 2 rigid-axle fields of issue
  // 17; + the 6 leaf-spring fields and the leaf balance's rocker of issue 17), 15 scalars, gear and the 3 model-validity
  // fields, num_joints, 1 joint x 5, num_diffs (issue 17; the synthetic model has no
  // differentials: no diff columns).
  EXPECT_EQ(state.header.size(),
            8u + 2u * (15u + 3u) + 1u + 6u * (26u + 7u) + 15u + 3u + 2u + 5u + 1u);
  EXPECT_EQ(state.rows[123].size(), state.header.size());
  EXPECT_EQ(state.number(123, "cycle"), 123.0);
  EXPECT_EQ(state.number(123, "sim_time_s"), 0.123);
  EXPECT_EQ(state.number(123, "unit1_x_m"), 20.0 * 0.123 - 6.0);
  EXPECT_EQ(state.number(123, "wheel0_spin_radps"), 30.0 + 0.01 * 123.0);
  EXPECT_EQ(state.number(123, "wheel5_spin_radps"), 30.0 + 0.01 * 123.0 + 11.0);
  EXPECT_EQ(state.number(123, "wheel5_unit"), 1.0);
  EXPECT_EQ(state.number(123, "wheel3_slip_x"), 0.003);
  EXPECT_EQ(state.number(123, "steering_wheel_angle_rad"), 0.0001 * 123.0);
  EXPECT_EQ(state.number(123, "joint0_force_x_n"), 1123.0);
  EXPECT_EQ(state.number(123, "joint0_rod_force_n"), -623.0);
  EXPECT_EQ(state.number(123, "lateness_ns"), 123 % 97 * 1000.0);
  EXPECT_EQ(state.number(123, "timestamp_us") - state.number(0, "timestamp_us"), 123'000.0);

  const Table signals = read_csv(dir / "RIG_SIGNALS.csv");
  ASSERT_EQ(signals.rows.size(), 30u);
  EXPECT_EQ(signals.number(2, "vehicle_speed_mps"), 7.0 + 0.001 * 20.0);
  EXPECT_EQ(signals.number(2, "vehicle_speed_mps_valid"), 1.0);
  EXPECT_EQ(signals.rows[2][signals.column("steering_wheel_angle_cmd_rad_source")], "driver");
  EXPECT_EQ(signals.rows[2][signals.column("steering_wheel_torque_cmd_nm_source")], "can");

  const Table status = read_csv(dir / "RIG_STATUS.csv");
  ASSERT_EQ(status.rows.size(), 3u);
  EXPECT_EQ(status.number(2, "cycles"), 201.0);
  EXPECT_EQ(status.number(2, "can_frames_received"), 600.0);
  EXPECT_EQ(status.number(2, "input_valid_assist_torque_nm"), 1.0);
  EXPECT_EQ(status.rows[2][status.column("bus_state")], "up");

  const Table other = read_csv(dir / "OTHER_TOOL.csv");
  ASSERT_EQ(other.rows.size(), 1u);
  EXPECT_EQ(other.header, (std::vector<std::string>{"timestamp_us", "channel", "size_bytes"}));
  EXPECT_EQ(other.rows[0], (std::vector<std::string>{"42", "OTHER/TOOL", "5"}));

  std::filesystem::remove(file);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rig::io
