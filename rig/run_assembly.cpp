#include "rig/run_assembly.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "io/can/mapping/can_mapping.h"
#include "io/config/config_error.h"
#include "io/log/output_file.h"
#include "rig/model_factory.h"
#include "rig/sinks.h"

namespace rig {
namespace {

template <typename T>
std::vector<T*> pointers(const std::vector<std::unique_ptr<T>>& owned) {
  std::vector<T*> out;
  out.reserve(owned.size());
  for (const auto& p : owned) out.push_back(p.get());
  return out;
}

/// A bad command line found after the configuration was read (exit 2).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// --duration: finite, > 0 and at least one period (0 or none: [rig] duration_s).
void check_duration(const RunOptions& options, const RigConfig& config) {
  if (!options.duration_s) return;
  const double d = *options.duration_s;
  char text[200];
  if (!std::isfinite(d) || !(d > 0)) {
    std::snprintf(text, sizeof text,
                  "--duration %g: must be a finite number of seconds > 0 (to run until stopped, "
                  "leave it out with [rig] duration_s = 0)",
                  d);
    throw UsageError(text);
  }
  if (d < config.rig.period_s) {
    std::snprintf(text, sizeof text, "--duration %g s is shorter than one period (%g s)", d,
                  config.rig.period_s);
    throw UsageError(text);
  }
}

/// What the run reads: no output may overwrite it.
std::vector<std::filesystem::path> input_files(const RigConfig& c) {
  std::vector<std::filesystem::path> in{c.file};
  if (c.model.vehicle) in.push_back(c.model.vehicle->file);
  if (c.model.combination) {
    for (const auto& f : c.model.combination->unit_files) in.push_back(f);
  }
  if (c.can) {
    in.push_back(c.can->mapping_file);
    in.push_back(c.can->dbc_file ? *c.can->dbc_file
                                 : io::can::mapping::mapping_dbc_path(c.can->mapping_file));
  }
  return in;
}

/// An output written at the end (null if not asked for), created now.
std::unique_ptr<std::FILE, FileCloser> open_file(const char* option, const std::string& path,
                                                 int keep) {
  if (path.empty()) return nullptr;
  const int fd = io::log::open_output_file({option, path}, keep);
  std::unique_ptr<std::FILE, FileCloser> f(::fdopen(fd, "w"));
  if (!f) throw io::log::OutputFileError(std::string(option) + ": fdopen failed");
  return f;
}

/// The outputs, last: an earlier run's files are rotated only when everything else loaded.
void open_outputs(const RunOptions& options, RunParts& parts) {
  const int keep = parts.config.rig.keep_logs;
  io::log::check_output_paths({{"--overrun-log", options.overrun_log},
                               {"--lcm-log", options.lcm_log},
                               {"--summary-json", options.summary_json},
                               {"--junit", options.junit}},
                              input_files(parts.config));
  parts.sinks = make_sinks(parts.config, options);
  if (!parts.config.kpis.empty())
    parts.kpis = std::make_unique<kpi::KpiRecorder>(parts.config.kpis);
  parts.log = std::make_unique<EventLog>(options.overrun_log, 4096, keep);
  parts.summary = open_file("--summary-json", options.summary_json, keep);
  parts.junit = open_file("--junit", options.junit, keep);
}

}  // namespace

std::vector<io::CycleIo*> RunParts::io_adapters() const { return pointers(io); }
std::vector<io::SnapshotSink*> RunParts::snapshot_sinks() const {
  std::vector<io::SnapshotSink*> out = pointers(sinks);
  if (kpis) out.push_back(kpis.get());
  return out;
}

ExecutiveParams executive_params(const RigConfig& config, const RunOptions& options) {
  ExecutiveParams p;
  p.period_s = config.rig.period_s;
  p.duration_s = options.duration_s ? *options.duration_s : config.rig.duration_s;
  p.offline = options.offline;
  p.policy = config.rig.policy;
  p.abort_after = config.rig.abort_after;
  p.priority = options.priority ? *options.priority : config.rig.priority;
  p.cpu = options.cpu ? *options.cpu : config.rig.cpu;
  p.stall_cycle = options.stall_cycle;
  p.stall_ms = options.stall_ms;
  p.lockstep = options.lockstep;
  p.hold_on_vehicle_fault = config.rig.hold_on_vehicle_fault;
  if (config.model.vehicle) p.unit_files.push_back(config.model.vehicle->file.string());
  if (config.model.combination) {
    for (const auto& f : config.model.combination->unit_files) p.unit_files.push_back(f.string());
  }
  return p;
}

int assemble(const RunOptions& options, RunParts& parts) {
  try {
    parts.config = load_config(options.config_file, io::config::Overrides(options.sets));
    check_duration(options, parts.config);
    parts.io = make_io(parts.config, options);
    parts.model = make_model(parts.config);
    parts.driver = make_driver(parts.config);
    if (!parts.config.events.empty())
      parts.events = std::make_unique<driver::EventStage>(parts.config.events);
    open_outputs(options, parts);
  } catch (const io::config::ConfigError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "rig: " << e.what() << "\n";
    return 2;
  } catch (const io::log::OutputFileError& e) {
    std::cerr << "rig: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rig: " << e.what() << "\n";
    return 1;
  }
  parts.params = executive_params(parts.config, options);
  return 0;
}

}  // namespace rig
