#pragma once
/// @file
/// What the executive needs to put LCM into its list of snapshot sinks.

#include <memory>
#include <string>

#include "io/lcm/lcm_settings.h"
#include "io/snapshot_sink.h"

namespace rig::io::lcm {

/// The live publisher (`--lcm-url URL`). Never throws for a missing network: it reports once and
/// turns itself off at start().
std::unique_ptr<SnapshotSink> make_lcm_publisher(const LcmSettings& settings);

/// An LCM event log file writer (`--lcm-log FILE`; an earlier FILE kept as FILE.1 .. FILE.keep).
/// Throws io::log::OutputFileError if FILE cannot be created.
std::unique_ptr<SnapshotSink> make_lcm_log_writer(const std::string& path,
                                                  const LcmSettings& settings, int keep = 10);

}  // namespace rig::io::lcm
