#pragma once
/// @file
/// `rig run`, assembly: the configuration and everything built from it before the loop starts
/// (model, driver, I/O adapters, sinks, event log, executive parameters).

#include <cstdio>
#include <memory>
#include <vector>

#include "io/cycle_io.h"
#include "io/snapshot_sink.h"
#include "model/stepped_model.h"
#include "rig/config.h"
#include "rig/driver/driver.h"
#include "rig/event_log.h"
#include "rig/executive.h"
#include "rig/kpi/kpi_recorder.h"
#include "rig/run_options.h"

namespace rig {

/// Closes a FILE* (the summary file; its errors are checked where it is written).
struct FileCloser {
  void operator()(std::FILE* f) const noexcept { (void)std::fclose(f); }
};

struct RunParts {
  RigConfig config;
  ExecutiveParams params;
  std::vector<std::unique_ptr<io::CycleIo>> io;
  std::vector<std::unique_ptr<io::SnapshotSink>> sinks;
  std::unique_ptr<model::SteppedModel> model;
  std::unique_ptr<driver::Driver> driver;
  /// [[event]]: run at the driver stage after the driver; null without [[event]].
  std::unique_ptr<driver::EventStage> events;
  std::unique_ptr<EventLog> log;
  /// [[kpi]]: records their signals (the last snapshot sink); null without [[kpi]].
  std::unique_ptr<kpi::KpiRecorder> kpis;
  /// --summary-json, created before the loop starts (written at the end); null if none.
  std::unique_ptr<std::FILE, FileCloser> summary;
  /// --junit, likewise.
  std::unique_ptr<std::FILE, FileCloser> junit;

  [[nodiscard]] std::vector<io::CycleIo*> io_adapters() const;
  [[nodiscard]] std::vector<io::SnapshotSink*> snapshot_sinks() const;
};

/// The executive's parameters: [rig], overridden by the command line.
ExecutiveParams executive_params(const RigConfig& config, const RunOptions& options);

/// Builds every part. On failure prints the error to stderr and returns the exit code (2: the
/// configuration, the command line or an output path; 1: anything else); 0 when `parts` is
/// complete. Every output file is checked (not twice, not an input, not a symbolic link) and
/// then created (earlier ones rotated, io/log/output_file.h) only after everything else loaded.
int assemble(const RunOptions& options, RunParts& parts);

}  // namespace rig
