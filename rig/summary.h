#pragma once
/// @file
/// The run summary: a one-line status (stderr, systemd STATUS=), a multi-line report at exit and
/// the --summary-json document.

#include <string>
#include <utility>
#include <vector>

#include "io/snapshot_sink.h"

#include "rig/executive.h"
#include "rig/kpi/kpi_recorder.h"

namespace rig {

struct SummaryExtras {
  double wall_time_s = 0;  ///< real elapsed time of the run (CLOCK_MONOTONIC)
  std::string stop_reason;
  int exit_code = 0;
  std::uint64_t events_lost = 0;
  std::vector<io::WriteFailures> write_failures;  ///< outputs that lost data (a full disk)
  std::vector<kpi::KpiResult> kpis;               ///< [[kpi]] of the configuration (rig/kpi)
  /// [[event]]: each event's name and when it fired [s] (NaN: never; null in JSON).
  std::vector<std::pair<std::string, double>> scenario_events;
  std::string config_file;        ///< --config
  std::vector<std::string> sets;  ///< --set KEY=VALUE, in order
};

/// The status line (rig/status_line.h) of the executive's figures so far.
std::string summary_line(const Executive& exec);
/// Multi-line report including a log-scale lateness histogram.
std::string summary_report(const Executive& exec, const SummaryExtras& extras);
/// The JSON document (keys: cycles, deadline_misses, sim_time_s, wall_time_s, drift_s,
/// lateness_ns, compute_ns, phase_max_ns, histogram, rt, policy, can, outputs, kpis, ...).
std::string summary_json(const Executive& exec, const SummaryExtras& extras);

}  // namespace rig
