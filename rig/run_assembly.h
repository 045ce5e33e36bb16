#pragma once
/// @file
/// `rig run`, assembly: the configuration and everything built from it before the loop starts
/// (model, driver, I/O adapters, sinks, event log, executive parameters).

#include <memory>
#include <vector>

#include "io/cycle_io.h"
#include "io/snapshot_sink.h"
#include "model/stepped_model.h"
#include "rig/config.h"
#include "rig/driver/driver.h"
#include "rig/event_log.h"
#include "rig/executive.h"
#include "rig/run_options.h"

namespace rig {

struct RunParts {
  RigConfig config;
  ExecutiveParams params;
  std::vector<std::unique_ptr<io::CycleIo>> io;
  std::vector<std::unique_ptr<io::SnapshotSink>> sinks;
  std::unique_ptr<model::SteppedModel> model;
  std::unique_ptr<driver::Driver> driver;
  std::unique_ptr<EventLog> log;

  [[nodiscard]] std::vector<io::CycleIo*> io_adapters() const;
  [[nodiscard]] std::vector<io::SnapshotSink*> snapshot_sinks() const;
};

/// The executive's parameters: [rig], overridden by the command line.
ExecutiveParams executive_params(const RigConfig& config, const RunOptions& options);

/// Builds every part. On failure prints the error to stderr and returns the exit code (2: the
/// configuration, 1: anything else); 0 when `parts` is complete.
int assemble(const RunOptions& options, RunParts& parts);

}  // namespace rig
