#include "rig/run_assembly.h"

#include <iostream>
#include <stdexcept>

#include "io/config/config_error.h"
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

}  // namespace

std::vector<io::CycleIo*> RunParts::io_adapters() const { return pointers(io); }
std::vector<io::SnapshotSink*> RunParts::snapshot_sinks() const { return pointers(sinks); }

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
  p.hold_on_vehicle_fault = config.rig.hold_on_vehicle_fault;
  if (config.model.vehicle) p.unit_files.push_back(config.model.vehicle->file.string());
  if (config.model.combination) {
    for (const auto& f : config.model.combination->unit_files) p.unit_files.push_back(f.string());
  }
  return p;
}

int assemble(const RunOptions& options, RunParts& parts) {
  try {
    parts.config = load_config(options.config_file);
    parts.io = make_io(parts.config, options);
    parts.sinks = make_sinks(parts.config, options);
    parts.model = make_model(parts.config);
    parts.driver = make_driver(parts.config);
  } catch (const io::config::ConfigError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rig: " << e.what() << "\n";
    return 1;
  }
  try {
    parts.log = std::make_unique<EventLog>(options.overrun_log);
  } catch (const std::exception& e) {
    std::cerr << "rig: " << e.what() << "\n";
    return 1;
  }
  parts.params = executive_params(parts.config, options);
  return 0;
}

}  // namespace rig
