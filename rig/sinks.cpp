#include "rig/sinks.h"

#include <iostream>
#include <string>
#include <utility>

#include "io/can/bridge/can_settings.h"
#include "io/config/config_error.h"
#include "io/lcm/lcm_settings.h"
#include "io/lcm/lcm_sinks.h"

namespace rig {

namespace {

/// Every input routed to CAN must be received by the mapping, else it is never written.
void check_can_routes(const RigConfig& config, const io::can::mapping::CanConfig& can) {
  io::InputSet received;
  for (const auto& message : can.mapping.rx) {
    for (const auto& s : message.signals) {
      if (s.model) received.set(s.model->slot);
    }
  }
  for (std::size_t i = 0; i < model::kSlotCount; ++i) {
    if (!config.routing.can_inputs[i] || received[i]) continue;
    throw io::config::ConfigError(config.can_route_at[i].at + ": [routing] " +
                                  config.can_route_at[i].name +
                                  ": routed to \"can\", but no [[rx]] signal of " +
                                  config.can->mapping_file.string() + " receives it");
  }
}

std::string can_input_names(const RigConfig& config, const io::InputSet& inputs) {
  std::string names;
  for (std::size_t i = 0; i < model::kSlotCount; ++i) {
    if (inputs[i]) names += (names.empty() ? "" : ", ") + config.can_route_at[i].name;
  }
  return names.empty() ? "none" : names;
}

}  // namespace

std::vector<std::unique_ptr<io::CycleIo>> make_io(const RigConfig& config,
                                                  const RunOptions& options) {
  std::vector<std::unique_ptr<io::CycleIo>> io;
  const bool can_off = options.can == "none";
  if (!config.can) {  // `--can IFACE` needs a mapping: a config with [can]
    if (!options.can.empty() && !can_off)
      throw io::config::ConfigError("rig: --can " + options.can + ": " + config.file.string() +
                                    " has no [can] section (no mapping to use; e.g. "
                                    "config/bench.toml has one)");
    return io;
  }
  io::can::bridge::CanSettings can = *config.can;
  if (!options.can.empty() && !can_off) can.interface = options.can;
  io::can::mapping::CanConfig files = io::can::bridge::load_can_files(can);
  for (const auto& note : files.database.warnings) std::cerr << "rig: warning: " << note << "\n";
  for (const auto& note : files.mapping.warnings) std::cerr << "rig: warning: " << note << "\n";
  check_can_routes(config, files);
  if (can_off) {
    std::cerr << "rig: warning: --can none: CAN is off although " << config.file.string()
              << " has [can]; the inputs routed to it ("
              << can_input_names(config, config.routing.can_inputs)
              << ") take their mapping fallback, flagged invalid\n";
    io.push_back(io::can::bridge::make_can_fallback_io(files, config.routing.can_inputs));
    return io;
  }
  io.push_back(io::can::bridge::make_can_io(std::move(files), can, config.routing.can_inputs));
  return io;
}

std::vector<std::unique_ptr<io::SnapshotSink>> make_sinks(const RigConfig& config,
                                                          const RunOptions& options) {
  std::vector<std::unique_ptr<io::SnapshotSink>> sinks;
  // LCM: [lcm] settings; --lcm-url overrides the URL ("none": no publisher), --lcm-log adds a
  // log file writer (the file is opened here, so a bad path fails before the loop starts).
  io::lcm::LcmSettings lcm = config.lcm;
  if (!options.lcm_url.empty()) lcm.url = options.lcm_url;
  if (lcm.url != "none") {
    if (const std::string warning = io::lcm::lcm_url_warning(lcm.url); !warning.empty())
      std::cerr << warning << "\n";
    sinks.push_back(io::lcm::make_lcm_publisher(lcm));
  }
  if (!options.lcm_log.empty())
    sinks.push_back(io::lcm::make_lcm_log_writer(options.lcm_log, lcm, config.rig.keep_logs));
  return sinks;
}

}  // namespace rig
