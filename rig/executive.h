#pragma once
/// @file
/// The real-time executive: a loop thread that every period runs the phases inputs (CycleIo),
/// driver, model step, outputs (CycleIo) and handoff (a snapshot into a lock-free ring), measures
/// each cycle, applies the overrun policy and logs misses; plus a non-RT dispatcher thread that
/// feeds the snapshot sinks. Statistics are fixed-bucket histograms updated on the loop thread
/// (a few adds per cycle, no I/O) so that dropped snapshots never bias them.

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "io/cycle_io.h"
#include "io/log/event_log.h"
#include "io/snapshot.h"
#include "io/snapshot_sink.h"
#include "model/stepped_model.h"
#include "rig/clock.h"
#include "rig/config.h"
#include "rig/driver/driver.h"
#include "rig/log_histogram.h"
#include "rig/spsc_ring.h"

namespace rig {

struct ExecutiveParams {
  double period_s = 0.001;
  double duration_s = 0.0;  ///< 0: until request_stop()
  bool offline = false;     ///< the ring applies back-pressure instead of dropping (determinism)
  OverrunPolicy policy = OverrunPolicy::kSkip;
  int abort_after = 10;
  int priority = 80;  ///< SCHED_FIFO priority (start() only)
  int cpu = -1;       ///< CPU affinity (start() only)
  std::size_t snapshot_capacity = 256;
  std::uint64_t stall_cycle = 0;  ///< test hook: stall this cycle's model phase ...
  std::int64_t stall_ms = 0;      ///< ... for this long (0: never)
};

enum class StopReason { kNone, kDuration, kRequested, kAbortAfter, kNonFinite, kRtRefused };
const char* stop_reason_name(StopReason reason);

/// Test hook called on the loop thread at the end of every cycle.
class CycleHook {
 public:
  virtual ~CycleHook() = default;
  virtual void on_cycle(std::uint64_t cycle) noexcept = 0;
};

class Executive {
 public:
  /// Every pointer must outlive the executive; `driver` may be null. `routing` sets the sources
  /// of the input signals. Allocates everything here.
  Executive(const ExecutiveParams& params, Clock& clock, model::SteppedModel& model,
            driver::Driver* driver, std::vector<io::CycleIo*> io,
            std::vector<io::SnapshotSink*> sinks, io::log::EventLog& log,
            const std::array<model::SignalSource, model::kSignalCount>& routing);
  ~Executive();
  Executive(const Executive&) = delete;
  Executive& operator=(const Executive&) = delete;

  /// Runs the loop on the calling thread until it stops (no RT settings, no dispatcher: for tests
  /// with a fake clock; snapshots are drained by drain_snapshots()).
  StopReason run_loop();

  /// Applies mlockall, starts the dispatcher and the loop thread (SCHED_FIFO, affinity, timer
  /// slack 1 ns). The loop waits until go() (so that READY and the RT events come first).
  /// Returns what was granted.
  io::RunInfo prepare(const std::string& config_file);
  void go();
  /// Waits for the loop and the dispatcher to finish; sinks are stopped.
  StopReason join();
  /// Async-signal-safe.
  void request_stop() noexcept { stop_requested_.store(true, std::memory_order_relaxed); }
  [[nodiscard]] bool finished() const noexcept { return finished_.load(std::memory_order_acquire); }

  void set_hook(CycleHook* hook) noexcept { hook_ = hook; }

  /// Drains the snapshot ring into the sinks (dispatcher body); returns how many it consumed.
  std::size_t drain_snapshots();

  // ---- statistics (readable from any thread; exact once the loop has stopped) ----
  [[nodiscard]] std::uint64_t cycles() const noexcept {
    return cycles_.load(std::memory_order_acquire);
  }
  [[nodiscard]] std::uint64_t deadline_misses() const noexcept {
    return misses_.load(std::memory_order_relaxed);
  }
  [[nodiscard]] std::uint64_t skipped_periods() const noexcept {
    return skipped_.load(std::memory_order_relaxed);
  }
  [[nodiscard]] std::uint64_t snapshots_dropped() const noexcept {
    return dropped_.load(std::memory_order_relaxed);
  }
  [[nodiscard]] double sim_time_s() const noexcept {
    return sim_time_s_.load(std::memory_order_relaxed);
  }
  /// Loop-clock time since the start [s] (virtual time when offline).
  [[nodiscard]] double loop_time_s() const noexcept {
    return loop_time_s_.load(std::memory_order_relaxed);
  }
  [[nodiscard]] const LogHistogram& lateness() const noexcept { return lateness_; }
  [[nodiscard]] const LogHistogram& compute() const noexcept { return compute_; }
  [[nodiscard]] const LogHistogram& phase(io::Phase p) const noexcept {
    return phases_[static_cast<std::size_t>(p)];
  }
  [[nodiscard]] const model::Signals& signals() const noexcept {
    return signals_;
  }  ///< after the loop stopped
  [[nodiscard]] io::IoCounters can_counters() const noexcept;
  [[nodiscard]] const io::RunInfo& run_info() const noexcept { return info_; }

 private:
  void loop_thread_main();
  void dispatcher_main();
  void handoff(const io::CycleTiming& timing, std::int64_t& handoff_end_ns) noexcept;

  ExecutiveParams params_;
  Clock& clock_;
  model::SteppedModel& model_;
  driver::Driver* driver_;
  std::vector<io::CycleIo*> io_;
  std::vector<io::SnapshotSink*> sinks_;
  io::log::EventLog& log_;
  CycleHook* hook_ = nullptr;

  model::Signals signals_{};
  SpscRing<io::Snapshot> ring_;
  std::uint64_t dropped_since_consume_ = 0;  // dispatcher side
  std::uint64_t dropped_seen_ = 0;           // dispatcher side

  LogHistogram lateness_;
  LogHistogram compute_;
  std::array<LogHistogram, io::kPhaseCount> phases_;
  std::atomic<std::uint64_t> cycles_{0};
  std::atomic<std::uint64_t> misses_{0};
  std::atomic<std::uint64_t> skipped_{0};
  std::atomic<std::uint64_t> dropped_{0};
  std::atomic<double> sim_time_s_{0};
  std::atomic<double> loop_time_s_{0};

  io::RunInfo info_;
  std::thread loop_thread_;
  std::thread dispatcher_;
  std::atomic<bool> stop_requested_{false};
  std::atomic<bool> go_{false};
  std::atomic<bool> rt_ready_{false};
  std::atomic<bool> finished_{false};
  StopReason reason_ = StopReason::kNone;
};

}  // namespace rig
