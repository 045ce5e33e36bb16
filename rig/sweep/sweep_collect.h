#pragma once
/// @file
/// A sweep's results: each run's status.json and summary.json read back into DIR/campaign.csv
/// (one row per run), DIR/junit.xml (one <testsuite> per run) and, by scripts/plot campaign,
/// DIR/plots/*.png.
///
/// campaign.csv's columns: id, maneuver, road, seed, one per [[vary]] key (the key path as
/// the header), status, exit_code, stop_reason, sim_time_s, wall_time_s, kpis_failed, error,
/// then per KPI (the union over the runs, in plan order) `NAME` (its value) and `NAME.passed`
/// (1 or 0; empty without a value). status: ok | kpi_failed (the run ended as asked, a KPI
/// outside its limits) | failed (exit 1) | bad_config (exit 2) | output_lost (exit 3) |
/// interrupted (stopped by a signal before its end) | killed (died of a signal) | missing (no
/// status: never ran, or still running).

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "rig/kpi/kpi_recorder.h"
#include "rig/sweep/sweep_plan.h"

namespace rig::sweep {

struct RunResult {
  std::string status = "missing";
  int exit_code = -1;  ///< -1: no status.json
  std::string stop_reason;
  std::string started;                         ///< the run's start, ISO 8601 (UTC)
  double sim_time_s = 0.0, wall_time_s = 0.0;  ///< NaN when unknown (read_result)
  std::vector<kpi::KpiResult> kpis;
  std::string error;  ///< the last line of rig.log when the run did not end as asked
};

RunResult read_result(const Plan& plan, const SweepRun& run);

struct Campaign {
  std::size_t runs = 0, ok = 0, kpi_failed = 0, failed = 0;  ///< failed: any other status
  std::filesystem::path csv;
};

/// Writes campaign.csv and junit.xml (and the plots if `plots`); throws std::runtime_error if
/// campaign.csv cannot be written.
Campaign collect(const Plan& plan, bool plots);

/// 1 if a run did not end as asked (or never ran); else 3 if `fail_on_kpi` and a KPI failed;
/// else 0.
int sweep_exit_code(const Campaign& c, bool fail_on_kpi);

}  // namespace rig::sweep
