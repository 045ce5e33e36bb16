#include "rig/sinks.h"

#include "io/lcm/lcm_sinks.h"

#include "io/lcm/lcm_sinks.h"

namespace rig {

std::vector<std::unique_ptr<io::CycleIo>> make_io(const RigConfig& /*config*/,
                                                  const RunOptions& /*options*/) {
  std::vector<std::unique_ptr<io::CycleIo>> io;
  // CAN (io/can/bridge make_can_io) plugs in here when [can] is parsed and --can is not "none".
  return io;
}

std::vector<std::unique_ptr<io::SnapshotSink>> make_sinks(const RigConfig& config,
                                                          const RunOptions& options) {
  std::vector<std::unique_ptr<io::SnapshotSink>> sinks;
  // LCM: [lcm] settings; --lcm-url overrides the URL ("none": no publisher), --lcm-log adds a
  // log file writer (the file is opened here, so a bad path fails before the loop starts).
  io::LcmSettings lcm = config.lcm;
  if (!options.lcm_url.empty()) lcm.url = options.lcm_url;
  if (lcm.url != "none") sinks.push_back(io::make_lcm_publisher(lcm));
  if (!options.lcm_log.empty()) sinks.push_back(io::make_lcm_log_writer(options.lcm_log, lcm));
  return sinks;
}

}  // namespace rig
