#pragma once
/// @file
/// The real-time executive: a loop thread that every period runs the named phases inputs
/// (CycleIo), driver, model step, outputs (CycleIo) and handoff (a snapshot into a lock-free
/// ring), makes one overrun decision per cycle (rig/overrun_policy) and logs misses; the
/// dispatcher thread (rig/dispatcher) feeds the snapshot sinks. Statistics are fixed-bucket
/// histograms updated on the loop thread (a few adds per cycle, no I/O) so that dropped
/// snapshots never bias them.

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "io/cycle_io.h"
#include "io/snapshot.h"
#include "io/snapshot_sink.h"
#include "model/stepped_model.h"
#include "rig/dispatcher.h"
#include "rig/driver/driver.h"
#include "rig/driver/scenario_events.h"
#include "rig/event_log.h"
#include "rig/overrun_policy.h"
#include "rig/phase_timer.h"
#include "rig/rt/clock.h"
#include "rig/rt/event_count.h"
#include "rig/rt/log_histogram.h"
#include "rig/snapshot_handoff.h"

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
  /// A vehicle fault (model::SteppedModel::last_fault()) stops the loop (false), or freezes the
  /// model at its last fault-free state, outputs flagged invalid, the loop going on (true).
  bool hold_on_vehicle_fault = false;
  std::vector<std::string> unit_files;  ///< the vehicle file of each unit, to name a fault's
  /// rig run --lockstep (docs/can.md "Lock-step"): each cycle waits, at most lockstep_timeout_ns,
  /// for a received cycle frame (CycleIo::wait_cycle_frame) before its inputs; the wait is not
  /// lateness (the cycle's deadline moves to its end), a timeout is counted, logged, and the
  /// cycle runs on the held inputs. The adapters then run on the loop's grid (start + (cycle +
  /// 1) period): their timeouts and send grids count simulated periods.
  bool lockstep = false;
  std::int64_t lockstep_timeout_ns = 100'000'000;
};

enum class StopReason {
  kNone,
  kDuration,
  kRequested,
  kAbortAfter,
  kNonFinite,
  kVehicleFault,
  kRtRefused,
  kEvent  ///< a scenario event's do = "stop" (rig/driver/scenario_events.h)
};
const char* stop_reason_name(StopReason reason);

/// The cycle numbers of the answers (issue 15): a received cycle frame (the rack's position) is
/// answered by the next sent cycle frame (the tie-rod forces computed from it); counted by
/// tx_cycle - rx_cycle.
struct CycleFrameStats {
  std::uint64_t lockstep_waits = 0;     ///< cycles that waited (--lockstep)
  std::uint64_t lockstep_timeouts = 0;  ///< of these, without the frame in the timeout
  std::uint64_t lockstep_wait_max_ns = 0;
  std::uint64_t received = 0;  ///< cycles that took in a received cycle frame
  std::uint64_t answered_same_cycle = 0;
  std::uint64_t answered_next_cycle = 0;
  std::uint64_t answered_later = 0;  ///< tx - rx > 1 (each one logged, "late_answer")
  std::int64_t last_rx_cycle = -1;   ///< the last answered or pending rx cycle
  std::int64_t last_tx_cycle = -1;
};

/// Test hook called on the loop thread at the end of every cycle.
class CycleHook {
 public:
  virtual ~CycleHook() = default;
  virtual void on_cycle(std::uint64_t cycle) noexcept = 0;
};

class Executive {
 public:
  using Sources = std::array<model::SignalSource, model::kSlotCount>;

  /// Every pointer must outlive the executive; `driver` may be null. `sources` (rig/routing) is
  /// published with every snapshot; nothing on the loop decides by it. Allocates everything here.
  Executive(const ExecutiveParams& params, rt::Clock& clock, model::SteppedModel& model,
            driver::Driver* driver, std::vector<io::CycleIo*> io,
            std::vector<io::SnapshotSink*> sinks, EventLog& log, const Sources& sources);
  ~Executive();
  Executive(const Executive&) = delete;
  Executive& operator=(const Executive&) = delete;

  /// Runs the loop on the calling thread until it stops (no RT settings, no dispatcher: for tests
  /// with a fake clock; snapshots are drained by drain_snapshots()).
  StopReason run_loop();

  /// Applies mlockall, starts the sinks, the loop thread (SCHED_FIFO, affinity, timer slack
  /// 1 ns) and the dispatcher. The loop waits until go() (so that READY and the RT events come
  /// first). Returns what was granted; rt_problems() says why not.
  io::RunInfo prepare(const std::string& config_file);
  void go();
  /// Waits for the loop and the dispatcher to finish; sinks are stopped.
  StopReason join();
  /// Async-signal-safe.
  void request_stop() noexcept;
  [[nodiscard]] bool finished() const noexcept { return handoff_.closed(); }
  /// Sleeps until the loop has finished, at most `timeout_ns` (the supervisor's wait).
  void wait_finished(std::int64_t timeout_ns) noexcept;

  void set_hook(CycleHook* hook) noexcept { hook_ = hook; }
  /// The scenario events, run at the driver stage after the driver (null: none). Before go().
  void set_events(driver::EventStage* events) noexcept { events_ = events; }

  /// Drains the snapshot ring into the sinks on the calling thread; returns how many.
  std::size_t drain_snapshots() { return dispatcher_.drain_snapshots(); }

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
  [[nodiscard]] std::uint64_t snapshots_dropped() const noexcept { return handoff_.dropped(); }
  [[nodiscard]] double sim_time_s() const noexcept {
    return sim_time_s_.load(std::memory_order_relaxed);
  }
  /// Loop-clock time since the start [s] (virtual time when offline).
  [[nodiscard]] double loop_time_s() const noexcept {
    return loop_time_s_.load(std::memory_order_relaxed);
  }
  [[nodiscard]] const rt::LogHistogram& lateness() const noexcept { return lateness_; }
  [[nodiscard]] const rt::LogHistogram& compute() const noexcept { return compute_; }
  [[nodiscard]] const rt::LogHistogram& phase(io::Phase p) const noexcept {
    return phases_[io::index(p)];
  }
  /// After the loop stopped.
  [[nodiscard]] const model::Signals& signals() const noexcept { return signals_; }
  /// The vehicle fault that stopped or froze the model (kind kNone: none), after the loop
  /// stopped; and the vehicle file of its unit ("" for the coupling or a model without files).
  [[nodiscard]] const model::ModelFault& vehicle_fault() const noexcept { return fault_; }
  [[nodiscard]] const std::string& fault_unit_file() const noexcept;
  /// The counters of every I/O adapter, summed (io/io_counters.h).
  [[nodiscard]] io::IoCounters io_counters() const noexcept {
    io::IoCounters sum{};
    read_io_counters(sum);
    return sum;
  }
  [[nodiscard]] const io::RunInfo& run_info() const noexcept { return info_; }
  /// The cycle frames' counts (exact once the loop has stopped).
  [[nodiscard]] const CycleFrameStats& cycle_frames() const noexcept { return cycle_frames_; }
  /// Why RT settings were refused ("" if all were granted), after prepare().
  [[nodiscard]] const std::string& rt_problems() const noexcept { return rt_problems_; }

 private:
  struct LoopState;
  StopReason cycle(LoopState& loop) noexcept;
  model::StepStatus step_model() noexcept;
  void fill_report() noexcept;
  void log_io_events(std::int64_t now_ns) noexcept;
  bool run_events() noexcept;
  void wait_lockstep(LoopState& loop, io::CycleTiming& t, std::int64_t io_ns) noexcept;
  [[nodiscard]] std::int64_t elapsed_ns(const LoopState& loop) const noexcept;
  void note_cycle_frames(std::uint64_t cycle, std::int64_t now_ns) noexcept;
  StopReason after_fault(model::StepStatus status, const io::CycleTiming& t,
                         std::int64_t end_ns) noexcept;
  OverrunDecision handoff(io::CycleTiming& timing, PhaseTimer& phases,
                          std::int64_t& end_ns) noexcept;
  void record(const io::CycleTiming& timing, const OverrunDecision& decision,
              std::int64_t end_ns) noexcept;
  void finish(StopReason reason) noexcept;
  void read_io_counters(io::IoCounters& sum) const noexcept;
  void loop_thread_main();
  void apply_rt_settings();

  ExecutiveParams params_;
  OverrunConfig overrun_;
  std::int64_t period_ns_;
  rt::Clock& clock_;
  model::SteppedModel& model_;
  driver::Driver* driver_;
  std::vector<io::CycleIo*> io_;
  EventLog& log_;
  CycleHook* hook_ = nullptr;
  driver::EventStage* events_ = nullptr;

  model::Signals signals_{};
  /// The cycle's report, filled after the step: what the adapters transmit from (catalogue
  /// outputs) and what the snapshot carries.
  model::ModelReport report_{};
  SnapshotHandoff handoff_;
  Dispatcher dispatcher_;
  std::uint32_t consecutive_misses_ = 0;  // loop thread
  std::int64_t start_ns_ = 0;             // loop thread
  model::ModelFault fault_{};             // loop thread; read after it stopped
  bool held_ = false;                     // loop thread: the model is frozen by a fault
  CycleFrameStats cycle_frames_{};        // loop thread; read after it stopped
  std::int64_t pending_rx_cycle_ = -1;    // loop thread: a received cycle frame not yet answered

  rt::LogHistogram lateness_;
  rt::LogHistogram compute_;
  std::array<rt::LogHistogram, io::kPhaseCount> phases_;
  std::atomic<std::uint64_t> cycles_{0};
  std::atomic<std::uint64_t> misses_{0};
  std::atomic<std::uint64_t> skipped_{0};
  std::atomic<double> sim_time_s_{0};
  std::atomic<double> loop_time_s_{0};

  io::RunInfo info_;
  std::string rt_problems_;
  std::thread loop_thread_;
  std::atomic<bool> stop_requested_{false};
  std::atomic<bool> go_{false};
  std::atomic<bool> rt_ready_{false};
  rt::EventCount finished_event_;
  StopReason reason_ = StopReason::kNone;
};

}  // namespace rig
