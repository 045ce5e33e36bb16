#pragma once
/// @file
/// Where the executive's pluggable parts are created from configuration and command line:
/// CycleIo adapters (CAN, ...) for the RT loop and SnapshotSinks (LCM, log writers) for the
/// dispatcher thread. Adapters land here as their helpers add them.

#include <memory>
#include <vector>

#include "io/cycle_io.h"
#include "io/snapshot_sink.h"
#include "rig/config.h"
#include "rig/run_options.h"

namespace rig {

/// CycleIo adapters. With [can]: loads the DBC and the mapping (their warnings on stderr, every
/// input routed to CAN must be received) and opens the bridge; `--can none` then gives one
/// warning line and the fallback adapter (those inputs at their mapping fallback, invalid).
/// Without [can]: none, and `--can IFACE` is an error. Throws ConfigError / runtime_error.
std::vector<std::unique_ptr<io::CycleIo>> make_io(const RigConfig& config,
                                                  const RunOptions& options);

/// Snapshot sinks for the dispatcher thread (`--lcm-url`, `--lcm-log`, ...).
std::vector<std::unique_ptr<io::SnapshotSink>> make_sinks(const RigConfig& config,
                                                          const RunOptions& options);

}  // namespace rig
