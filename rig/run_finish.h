#pragma once
/// @file
/// `rig run`, finish (after the loop and the dispatcher stopped): the stop event, the summary on
/// stderr and systemd STATUS, --summary-json, and the exit code.

#include <cstdint>

#include "io/systemd/notifier.h"
#include "rig/event_log.h"
#include "rig/executive.h"
#include "rig/rt/clock.h"
#include "rig/run_options.h"

namespace rig {

struct FinishInputs {
  StopReason reason = StopReason::kNone;
  int abort_after = 0;             ///< for the abort message
  std::int64_t wall_start_ns = 0;  ///< CLOCK_MONOTONIC at assembly's end
};

/// Returns the exit code: 0, or 1 (abort-after, non-finite model, a vehicle fault stopped or
/// held, unwritable summary file).
int finish_run(const Executive& exec, EventLog& log, const FinishInputs& in,
               const RunOptions& options, io::systemd::SystemdNotifier& notifier, rt::Clock& wall);

}  // namespace rig
