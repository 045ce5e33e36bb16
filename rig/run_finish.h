#pragma once
/// @file
/// `rig run`, finish (after the loop and the dispatcher stopped): the stop event, the summary on
/// stderr and systemd STATUS, --summary-json, and the exit code.

#include <cstdint>
#include <cstdio>
#include <vector>

#include "io/snapshot_sink.h"
#include "io/systemd/notifier.h"
#include "rig/event_log.h"
#include "rig/executive.h"
#include "rig/kpi/kpi_recorder.h"
#include "rig/rt/clock.h"
#include "rig/run_options.h"

namespace rig {

/// The run ended as asked, but an output lost data: a write failed (a full disk, an I/O error);
/// or, with --fail-on-kpi, a KPI failed its limits.
inline constexpr int kExitOutputLost = 3;
inline constexpr int kExitKpiFailed = 3;

struct FinishInputs {
  StopReason reason = StopReason::kNone;
  int abort_after = 0;                         ///< for the abort message
  std::int64_t wall_start_ns = 0;              ///< CLOCK_MONOTONIC at assembly's end
  std::vector<const io::SnapshotSink*> sinks;  ///< stopped: their write failures are final
  std::FILE* summary = nullptr;                ///< --summary-json, opened before the loop
  const kpi::KpiRecorder* kpis = nullptr;      ///< [[kpi]] (stopped), null if none
  const driver::EventStage* events = nullptr;  ///< [[event]], null if none
  std::FILE* junit = nullptr;                  ///< --junit, opened before the loop
};

/// Returns the exit code: 0; 1 (abort-after, non-finite model, a vehicle fault stopped or held);
/// else kExitOutputLost if any output failed to write (each failure: an event in the overrun
/// log if that still works, one stderr line, the summary's `write_failures`); else, with
/// --fail-on-kpi, kExitKpiFailed if a KPI failed (each one named on stderr in any case).
int finish_run(const Executive& exec, EventLog& log, const FinishInputs& in,
               const RunOptions& options, io::systemd::SystemdNotifier& notifier, rt::Clock& wall);

}  // namespace rig
