#pragma once
/// @file
/// The non-RT thread that drains the loop's snapshot ring into the sinks (LCM publisher, log
/// writers) and the event log's ring into its file. The loop never waits for it in real time;
/// offline it applies back-pressure (rig/snapshot_handoff.h).

#include <cstddef>
#include <thread>
#include <vector>

#include "io/snapshot_sink.h"
#include "rig/event_log.h"
#include "rig/snapshot_handoff.h"

namespace rig {

class Dispatcher {
 public:
  /// Every reference must outlive the dispatcher.
  Dispatcher(SnapshotHandoff& handoff, std::vector<io::SnapshotSink*> sinks, EventLog& log);
  ~Dispatcher();
  Dispatcher(const Dispatcher&) = delete;
  Dispatcher& operator=(const Dispatcher&) = delete;

  /// Calls every sink's start() (before the loop starts).
  void start_sinks(const io::RunInfo& info);
  /// Starts the thread: it drains until the loop has closed the handoff and the ring is empty,
  /// then stops the sinks.
  void start();
  void join();

  /// Hands every pending snapshot to the sinks on the calling thread; returns how many.
  std::size_t drain_snapshots();

 private:
  void thread_main();

  SnapshotHandoff& handoff_;
  std::vector<io::SnapshotSink*> sinks_;
  EventLog& log_;
  std::uint64_t dropped_seen_ = 0;
  std::thread thread_;
};

}  // namespace rig
