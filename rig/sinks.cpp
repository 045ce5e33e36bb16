#include "rig/sinks.h"

#include "io/can/bridge/can_settings.h"
#include "io/lcm/lcm_sinks.h"

namespace rig {

std::vector<std::unique_ptr<io::CycleIo>> make_io(const RigConfig& config,
                                                  const RunOptions& options) {
  std::vector<std::unique_ptr<io::CycleIo>> io;
  // CAN: a [can] section and not `--can none`; `--can IFACE` overrides the interface.
  if (config.can.has_value() && options.can != "none") {
    io::can::bridge::CanSettings can = *config.can;
    if (!options.can.empty()) can.interface = options.can;
    io.push_back(io::can::bridge::make_can_io(can, config.routing.can_inputs));
  }
  return io;
}

std::vector<std::unique_ptr<io::SnapshotSink>> make_sinks(const RigConfig& config,
                                                          const RunOptions& options) {
  std::vector<std::unique_ptr<io::SnapshotSink>> sinks;
  // LCM: [lcm] settings; --lcm-url overrides the URL ("none": no publisher), --lcm-log adds a
  // log file writer (the file is opened here, so a bad path fails before the loop starts).
  io::lcm::LcmSettings lcm = config.lcm;
  if (!options.lcm_url.empty()) lcm.url = options.lcm_url;
  if (lcm.url != "none") sinks.push_back(io::lcm::make_lcm_publisher(lcm));
  if (!options.lcm_log.empty())
    sinks.push_back(io::lcm::make_lcm_log_writer(options.lcm_log, lcm, config.rig.keep_logs));
  return sinks;
}

}  // namespace rig
