#pragma once
/// @file
/// The live LCM publisher: a SnapshotSink on the executive's non-RT dispatcher thread.

#include <cstdint>
#include <string>

#include "io/lcm/snapshot_encoder.h"
#include "io/snapshot_sink.h"

typedef struct _lcm_t lcm_t;

namespace rig::io::lcm {

/// Publishes RIG_STATE, RIG_SIGNALS and RIG_STATUS at their configured rates. If LCM cannot be
/// set up (no multicast route, bad URL) or a publish fails for good, it prints one message to
/// stderr and turns itself off; the run goes on.
class LcmPublisher final : public SnapshotSink {
 public:
  explicit LcmPublisher(LcmSettings settings);
  ~LcmPublisher() override;

  void start(const RunInfo& info) override;
  void consume(const Snapshot& snapshot, std::uint64_t dropped_before) override;
  void stop() override;

  /// True while LCM is up (after start(), until stop() or a fatal error).
  [[nodiscard]] bool active() const { return lcm_ != nullptr; }
  [[nodiscard]] std::uint64_t published() const { return published_; }
  /// Messages lost to transient send errors (ENOBUFS, EAGAIN).
  [[nodiscard]] std::uint64_t send_failures() const { return send_failures_; }

 private:
  void disable(const std::string& message);

  SnapshotEncoder encoder_;
  lcm_t* lcm_ = nullptr;
  std::uint64_t published_ = 0;
  std::uint64_t send_failures_ = 0;
};

}  // namespace rig::io::lcm
