#pragma once
/// @file
/// `rig run`: assembly (rig/run_assembly), real-time start (rig/run_start), supervision
/// (rig/run_supervision) and finish (rig/run_finish), with signal handling (rig/signals.h) and
/// a stderr that cannot block it (rig/stderr_relay.h).

#include "rig/config.h"
#include "rig/run_options.h"
#include "rig/sinks.h"

namespace rig {

/// Returns the process exit code: 0 ok, 2 configuration error or bad usage, 1 runtime failure,
/// 3 (kExitOutputLost, rig/run_finish.h) an output lost data.
int run(const RunOptions& options);

}  // namespace rig
