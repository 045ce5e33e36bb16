#include "io/lcm/lcm_sinks.h"

#include "io/lcm/lcm_log_writer.h"
#include "io/lcm/lcm_publisher.h"

namespace rig::io::lcm {

std::unique_ptr<SnapshotSink> make_lcm_publisher(const LcmSettings& settings) {
  return std::make_unique<LcmPublisher>(settings);
}

std::unique_ptr<SnapshotSink> make_lcm_log_writer(const std::string& path,
                                                  const LcmSettings& settings, int keep) {
  return std::make_unique<LcmLogWriter>(path, settings, keep);
}

}  // namespace rig::io::lcm
