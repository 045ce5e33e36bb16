#pragma once
/// @file
/// The one-line run status (stderr every [rig] status_interval_s, on SIGUSR1, systemd STATUS=):
/// a pure function of the figures, so that its text and width are unit-tested without a run.

#include <cstdint>
#include <string>

#include "io/io_counters.h"

namespace rig {

struct StatusFigures {
  std::uint64_t cycles = 0;
  std::uint64_t misses = 0;
  double sim_time_s = 0;
  std::int64_t lateness_p50_ns = 0, lateness_p99_ns = 0, lateness_p999_ns = 0, lateness_max_ns = 0;
  std::int64_t compute_p50_ns = 0, compute_p99_ns = 0, compute_max_ns = 0;
  io::IoCounters can;  ///< bus_state kDisabled: no CAN configured (or --can none)
};

/// Without CAN: "cycles 12000, misses 3, sim 12.000 s, lateness p50/p99/p99.9/max
/// 12.0/40.0/80.0/210.0 us, compute p50/p99/max 1.0/2.0/3.0 us". With CAN the timing shrinks to
/// the worst lateness ("late max") and the CAN counters and bus state follow, counts as
/// compact_count(), so that the line fits 120 columns whatever the counts: "cycles 86.4M, misses 3,
/// late max 1234 us, rx 8.64M tx 25.9M to 2 rej 5 oor 7, CAN up" (rx/tx: CAN frames received/sent;
/// to: message timeouts; rej: frames rejected for their alive counter or checksum; oor: values
/// clamped to their DBC range). The percentiles are in the summary and on RIG_STATUS.
std::string status_line(const StatusFigures& f);

/// A count in at most 5 characters: exact below 10000, else 3 significant digits and k/M/G/T
/// ("12.3k", "605M"), rounded down so that it never claims more than was counted.
std::string compact_count(std::uint64_t n);

}  // namespace rig
