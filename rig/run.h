#pragma once
/// @file
/// `rig run`: loads the configuration, builds model/driver/io/sinks, runs the executive with
/// signal handling, systemd notification, periodic status and the final summary.

#include "rig/config.h"
#include "rig/run_options.h"
#include "rig/sinks.h"

namespace rig {

/// Returns the process exit code: 0 ok, 2 configuration error, 1 runtime failure.
int run(const RunOptions& options);

}  // namespace rig
