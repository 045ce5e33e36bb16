#include "rig/executive.h"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/prctl.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace rig {
namespace {

std::int64_t to_ns(double s) { return std::llround(s * 1e9); }

void sleep_ms(std::int64_t ms) noexcept {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(ms / 1000);
  ts.tv_nsec = static_cast<long>((ms % 1000) * 1'000'000);
  while (nanosleep(&ts, &ts) != 0) {
  }
}

}  // namespace

const char* stop_reason_name(StopReason reason) {
  switch (reason) {
    case StopReason::kNone:
      return "none";
    case StopReason::kDuration:
      return "duration";
    case StopReason::kRequested:
      return "signal";
    case StopReason::kAbortAfter:
      return "abort-after";
    case StopReason::kNonFinite:
      return "non-finite";
    case StopReason::kRtRefused:
      return "rt-refused";
  }
  return "?";
}

Executive::Executive(const ExecutiveParams& params, Clock& clock, model::SteppedModel& model,
                     driver::Driver* driver, std::vector<io::CycleIo*> io,
                     std::vector<io::SnapshotSink*> sinks, io::log::EventLog& log,
                     const std::array<model::SignalSource, model::kSignalCount>& routing)
    : params_(params),
      clock_(clock),
      model_(model),
      driver_(driver),
      io_(std::move(io)),
      sinks_(std::move(sinks)),
      log_(log),
      ring_(params.snapshot_capacity) {
  signals_.source = routing;
  info_.period_s = params.period_s;
  info_.offline = params.offline;
  info_.policy = policy_name(params.policy, params.abort_after);
}

Executive::~Executive() {
  if (loop_thread_.joinable() || dispatcher_.joinable()) {
    request_stop();
    go_.store(true);
    join();
  }
}

io::IoCounters Executive::can_counters() const noexcept {
  io::IoCounters c{};
  if (!io_.empty()) io_.front()->read_counters(c);
  return c;
}

void Executive::handoff(const io::CycleTiming& timing, std::int64_t& handoff_end_ns) noexcept {
  io::Snapshot* slot = ring_.claim();
  if (slot == nullptr && params_.offline) {
    // Offline: wait for the dispatcher rather than drop, so that every sink sees every cycle.
    while ((slot = ring_.claim()) == nullptr && !stop_requested_.load(std::memory_order_relaxed)) {
      sched_yield();
    }
  }
  if (slot == nullptr) {
    dropped_.fetch_add(1, std::memory_order_relaxed);
  } else {
    slot->timing = timing;
    slot->signals = signals_;
    model_.fill_report(slot->report);
    if (!io_.empty()) {
      io_.front()->read_counters(slot->can);
    } else {
      slot->can = io::IoCounters{};
    }
  }
  handoff_end_ns = clock_.now_ns();
  if (slot != nullptr) {
    slot->timing.phase_ns[static_cast<std::size_t>(io::Phase::kHandoff)] =
        handoff_end_ns - timing.wake_ns - timing.compute_ns;
    ring_.commit();
  }
}

StopReason Executive::run_loop() {
  const std::int64_t period_ns = to_ns(params_.period_s);
  const std::int64_t duration_ns = to_ns(params_.duration_s);
  const std::int64_t start_ns = clock_.now_ns();
  std::int64_t deadline = start_ns + period_ns;
  std::uint32_t consecutive = 0;
  std::uint64_t cycle = 0;
  StopReason reason = StopReason::kNone;
  io::CycleTiming t{};
  char action[24];

  while (reason == StopReason::kNone) {
    if (stop_requested_.load(std::memory_order_relaxed)) {
      reason = StopReason::kRequested;
      break;
    }
    if (duration_ns > 0 && deadline - start_ns > duration_ns) {
      reason = StopReason::kDuration;
      break;
    }
    clock_.sleep_until(deadline);
    const std::int64_t wake = clock_.now_ns();
    t.cycle = cycle;
    t.deadline_ns = deadline;
    t.wake_ns = wake;
    t.lateness_ns = wake - deadline;

    for (io::CycleIo* a : io_) a->receive(wake, signals_);
    const std::int64_t t_inputs = clock_.now_ns();
    if (driver_ != nullptr) driver_->update(model_.time_s(), signals_);
    const std::int64_t t_driver = clock_.now_ns();
    if (params_.stall_ms > 0 && cycle == params_.stall_cycle) sleep_ms(params_.stall_ms);
    const model::StepStatus status = model_.step(signals_);
    const std::int64_t t_model = clock_.now_ns();
    for (io::CycleIo* a : io_) a->transmit(t_model, signals_);
    const std::int64_t t_outputs = clock_.now_ns();

    t.sim_time_s = model_.time_s();
    t.phase_ns[0] = t_inputs - wake;
    t.phase_ns[1] = t_driver - t_inputs;
    t.phase_ns[2] = t_model - t_driver;
    t.phase_ns[3] = t_outputs - t_model;
    t.phase_ns[4] = 0;
    t.compute_ns = t_outputs - wake;
    // Predict the miss before the handoff so the snapshot carries it; recomputed below.
    std::int64_t end = 0;
    t.deadline_miss = t_outputs > deadline + period_ns;
    t.consecutive_misses = t.deadline_miss ? consecutive + 1 : 0;
    handoff(t, end);
    t.phase_ns[4] = end - t_outputs;
    t.compute_ns = end - wake;
    t.deadline_miss = end > deadline + period_ns;  // work ended after the next deadline

    lateness_.add(t.lateness_ns);
    compute_.add(t.compute_ns);
    for (std::size_t p = 0; p < io::kPhaseCount; ++p) phases_[p].add(t.phase_ns[p]);
    sim_time_s_.store(t.sim_time_s, std::memory_order_relaxed);
    loop_time_s_.store(static_cast<double>(end - start_ns) * 1e-9, std::memory_order_relaxed);

    std::int64_t next = deadline + period_ns;
    if (t.deadline_miss) {
      ++consecutive;
      t.consecutive_misses = consecutive;
      misses_.fetch_add(1, std::memory_order_relaxed);
      if (params_.policy == OverrunPolicy::kCatchUp) {
        std::snprintf(action, sizeof action, "catch-up");
      } else {
        // skip (and abort-after until it fires): next deadline = first grid point after `end`.
        const std::int64_t k = (end - deadline) / period_ns + 1;
        next = deadline + k * period_ns;
        skipped_.fetch_add(static_cast<std::uint64_t>(k - 1), std::memory_order_relaxed);
        std::snprintf(action, sizeof action, "skip:%lld", static_cast<long long>(k - 1));
        if (params_.policy == OverrunPolicy::kAbortAfter &&
            consecutive >= static_cast<std::uint32_t>(params_.abort_after)) {
          std::snprintf(action, sizeof action, "abort");
          reason = StopReason::kAbortAfter;
        }
      }
      log_.miss(clock_.realtime_ns(), end, t, action);
    } else {
      consecutive = 0;
    }
    ++cycle;
    cycles_.store(cycle, std::memory_order_release);
    if (hook_ != nullptr) hook_->on_cycle(cycle);

    if (status == model::StepStatus::kNonFinite) {
      char detail[160];
      std::snprintf(detail, sizeof detail,
                    "model step produced a non-finite value at cycle %llu, t = %.6f s; stopping",
                    static_cast<unsigned long long>(t.cycle), t.sim_time_s);
      log_.event(clock_.realtime_ns(), end, "non_finite", detail);
      reason = StopReason::kNonFinite;
    }
    deadline = next;
  }
  reason_ = reason;
  finished_.store(true, std::memory_order_release);
  return reason;
}

std::size_t Executive::drain_snapshots() {
  std::size_t n = 0;
  while (const io::Snapshot* s = ring_.front()) {
    const std::uint64_t dropped = dropped_.load(std::memory_order_relaxed);
    for (io::SnapshotSink* sink : sinks_) sink->consume(*s, dropped - dropped_seen_);
    dropped_seen_ = dropped;
    ring_.release();
    ++n;
  }
  return n;
}

void Executive::dispatcher_main() {
  while (!finished_.load(std::memory_order_acquire)) {
    if (drain_snapshots() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  drain_snapshots();
  for (io::SnapshotSink* sink : sinks_) sink->stop();
}

void Executive::loop_thread_main() {
  // RT settings of this thread; the outcome goes into info_ before rt_ready_.
  prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
  if (!params_.offline) {
    sched_param sp{};
    sp.sched_priority = params_.priority;
    if (pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp) == 0) {
      info_.sched_fifo = true;
      info_.priority = params_.priority;
    }
  }
  if (params_.cpu >= 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(static_cast<std::size_t>(params_.cpu), &set);
    if (pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0) info_.cpu = params_.cpu;
  }
  rt_ready_.store(true, std::memory_order_release);
  while (!go_.load(std::memory_order_acquire))
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  if (stop_requested_.load()) {
    reason_ = StopReason::kRequested;
    finished_.store(true, std::memory_order_release);
    return;
  }
  run_loop();
}

io::RunInfo Executive::prepare(const std::string& config_file) {
  info_.config_file = config_file;
  if (!params_.offline) info_.memory_locked = mlockall(MCL_CURRENT | MCL_FUTURE) == 0;
  for (io::SnapshotSink* sink : sinks_) sink->start(info_);
  loop_thread_ = std::thread([this] { loop_thread_main(); });
  while (!rt_ready_.load(std::memory_order_acquire))
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  dispatcher_ = std::thread([this] { dispatcher_main(); });
  return info_;
}

void Executive::go() { go_.store(true, std::memory_order_release); }

StopReason Executive::join() {
  if (loop_thread_.joinable()) loop_thread_.join();
  if (dispatcher_.joinable()) dispatcher_.join();
  return reason_;
}

}  // namespace rig
