#pragma once
/// @file
/// A consumer of cycle snapshots on the non-RT side (LCM publisher, log writers). The executive's
/// dispatcher thread drains the loop's lock-free ring and calls every sink in order; the loop
/// never waits for a sink.

#include <cstdint>
#include <string>

#include "io/snapshot.h"

namespace rig::io {

/// What the executive was granted and how it runs; constant for a run.
struct RunInfo {
  double period_s = 0.001;
  bool offline = false;
  bool sched_fifo = false;     ///< SCHED_FIFO granted
  int priority = 0;            ///< granted priority (0 if none)
  bool memory_locked = false;  ///< mlockall granted
  int cpu = -1;                ///< pinned CPU, -1 if not pinned
  std::string policy;          ///< overrun policy: "skip", "catch-up" or "abort-after=N"
  std::string config_file;
};

/// What an output sink could not write (a full disk, an I/O error): counted, never silent.
struct WriteFailures {
  std::uint64_t count = 0;  ///< records (messages, lines) lost
  std::string what;         ///< e.g. "LCM log out/run.lcm: No space left on device"
};

class SnapshotSink {
 public:
  SnapshotSink() = default;
  SnapshotSink(const SnapshotSink&) = delete;
  SnapshotSink& operator=(const SnapshotSink&) = delete;
  virtual ~SnapshotSink() = default;

  /// Called once before the loop starts.
  virtual void start(const RunInfo& info) = 0;
  /// Called for every snapshot that reached the non-RT side, in cycle order. `dropped_before`
  /// is the number of snapshots the ring lost since the previous call (0 normally).
  virtual void consume(const Snapshot& snapshot, std::uint64_t dropped_before) = 0;
  /// Called once after the loop stopped and the ring is drained: flush and close.
  virtual void stop() = 0;
  /// After stop(): what a file-writing sink failed to write (none by default).
  [[nodiscard]] virtual WriteFailures write_failures() const { return {}; }
};

}  // namespace rig::io
