#pragma once
/// @file
/// Writes the LCM messages of a run straight into an LCM event log file (the format lcm-logger
/// writes and lcm-logplayer replays), from the non-RT dispatcher thread.

#include <cstdint>
#include <string>

#include "io/lcm/snapshot_encoder.h"
#include "io/snapshot_sink.h"

typedef struct _lcm_eventlog_t lcm_eventlog_t;

namespace rig::io::lcm {

/// Each event's timestamp is the wall-clock time at start() plus the snapshot's simulated time,
/// so that lcm-logplayer replays the run at its simulated pace even if it ran offline.
class LcmLogWriter final : public SnapshotSink {
 public:
  /// Creates `path` (io/log/output_file.h: an earlier file is kept as NAME.1 .. NAME.keep, a
  /// symbolic link refused); throws io::log::OutputFileError if it cannot.
  LcmLogWriter(const std::string& path, LcmSettings settings, int keep = 10);
  ~LcmLogWriter() override;

  void start(const RunInfo& info) override;
  void consume(const Snapshot& snapshot, std::uint64_t dropped_before) override;
  void stop() override;
  /// Events that could not be written (a full disk), counted until stop().
  [[nodiscard]] WriteFailures write_failures() const override;

  [[nodiscard]] std::uint64_t events_written() const { return events_written_; }

 private:
  SnapshotEncoder encoder_;
  std::string path_;
  lcm_eventlog_t* log_ = nullptr;
  std::int64_t start_utime_us_ = 0;
  std::uint64_t events_written_ = 0;
  std::uint64_t write_failures_ = 0;
  std::string write_error_;  ///< the first failure's errno text

  void failed(int error);
};

}  // namespace rig::io::lcm
