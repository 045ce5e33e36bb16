#include "rig/sinks.h"

namespace rig {

std::vector<std::unique_ptr<io::CycleIo>> make_io(const RigConfig& /*config*/,
                                                  const RunOptions& /*options*/) {
  std::vector<std::unique_ptr<io::CycleIo>> io;
  // CAN (io/can/bridge make_can_io) plugs in here when [can] is parsed and --can is not "none".
  return io;
}

std::vector<std::unique_ptr<io::SnapshotSink>> make_sinks(const RigConfig& /*config*/,
                                                          const RunOptions& /*options*/) {
  std::vector<std::unique_ptr<io::SnapshotSink>> sinks;
  // LCM (io/lcm make_lcm_publisher / make_lcm_log_writer) plugs in here for --lcm-url/--lcm-log.
  return sinks;
}

}  // namespace rig
