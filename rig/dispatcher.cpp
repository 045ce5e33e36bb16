#include "rig/dispatcher.h"

#include <utility>

#include "rig/signals.h"

namespace rig {
namespace {

/// Real time: how long the dispatcher sleeps between looks at the ring (the loop never signals).
constexpr std::int64_t kRealTimePollNs = 2'000'000;

}  // namespace

Dispatcher::Dispatcher(SnapshotHandoff& handoff, std::vector<io::SnapshotSink*> sinks,
                       EventLog& log)
    : handoff_(handoff), sinks_(std::move(sinks)), log_(log) {}

Dispatcher::~Dispatcher() { join(); }

void Dispatcher::start_sinks(const io::RunInfo& info) {
  for (io::SnapshotSink* sink : sinks_) sink->start(info);
}

void Dispatcher::start() {
  thread_ = start_thread([this] { thread_main(); });
}

void Dispatcher::join() {
  if (thread_.joinable()) thread_.join();
}

std::size_t Dispatcher::drain_snapshots() {
  std::size_t n = 0;
  while (const io::Snapshot* s = handoff_.front()) {
    const std::uint64_t dropped = handoff_.dropped();
    for (io::SnapshotSink* sink : sinks_) sink->consume(*s, dropped - dropped_seen_);
    dropped_seen_ = dropped;
    handoff_.release();
    ++n;
  }
  return n;
}

void Dispatcher::thread_main() {
  for (;;) {
    const bool closed = handoff_.closed();  // before the drain: nothing committed is left behind
    drain_snapshots();
    log_.drain();
    if (closed) break;
    handoff_.wait_for_work(kRealTimePollNs);
  }
  for (io::SnapshotSink* sink : sinks_) sink->stop();
}

}  // namespace rig
