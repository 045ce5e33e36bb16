#include "rig/executive.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

#include "rig/rt/thread_setup.h"
#include "rig/signals.h"
#include "rig/vehicle_fault_text.h"

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

/// Copies the report's scalars and the units, wheels and joints the model has. The rest is never
/// written (the shape is fixed at start), so it stays as value-initialised in both: the same
/// snapshot as a whole copy, without moving kilobytes of unused wheels each cycle.
void copy_report(const model::ModelReport& from, model::ModelReport& to) noexcept {
  to.time_s = from.time_s;
  to.unit_count = from.unit_count;
  for (int k = 0; k < from.unit_count && k < model::kMaxUnits; ++k) {
    const model::UnitReport& u = from.units[static_cast<std::size_t>(k)];
    model::UnitReport& v = to.units[static_cast<std::size_t>(k)];
    v.position_m = u.position_m;
    v.orientation_rad = u.orientation_rad;
    v.velocity_mps = u.velocity_mps;
    v.angular_velocity_radps = u.angular_velocity_radps;
    v.acceleration_mps2 = u.acceleration_mps2;
    v.frame_twist_rad = u.frame_twist_rad;
    v.frame_twist_rate_radps = u.frame_twist_rate_radps;
    v.frame_torsion_moment_nm = u.frame_torsion_moment_nm;
    v.wheel_count = u.wheel_count;
    for (int i = 0; i < u.wheel_count && i < model::kMaxWheelsPerUnit; ++i)
      v.wheels[static_cast<std::size_t>(i)] = u.wheels[static_cast<std::size_t>(i)];
  }
  to.steering = from.steering;
  to.drivetrain = from.drivetrain;
  to.brake_pressure_pa = from.brake_pressure_pa;
  to.joint_count = from.joint_count;
  to.joints = from.joints;
  to.differential_count = from.differential_count;
  to.differentials = from.differentials;
  to.body_count = from.body_count;
  to.bodies = from.bodies;
  to.valid = from.valid;
  to.fault_kind = from.fault_kind;
  to.fault_unit = from.fault_unit;
}

}  // namespace

/// The loop thread's position on the deadline grid.
struct Executive::LoopState {
  std::int64_t deadline_ns = 0;
  std::uint64_t cycle = 0;
};

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
    case StopReason::kVehicleFault:
      return "vehicle-fault";
    case StopReason::kRtRefused:
      return "rt-refused";
    case StopReason::kEvent:
      return "event";
  }
  return "?";
}

Executive::Executive(const ExecutiveParams& params, rt::Clock& clock, model::SteppedModel& model,
                     driver::Driver* driver, std::vector<io::CycleIo*> io,
                     std::vector<io::SnapshotSink*> sinks, EventLog& log, const Sources& sources)
    : params_(params),
      overrun_{params.policy, static_cast<std::uint32_t>(params.abort_after)},
      period_ns_(to_ns(params.period_s)),
      clock_(clock),
      model_(model),
      driver_(driver),
      io_(std::move(io)),
      log_(log),
      handoff_(params.snapshot_capacity, params.offline),
      dispatcher_(handoff_, std::move(sinks), log) {
  for (io::CycleIo* a : io_) a->set_cycle_frames(period_ns_);
  signals_.source = sources;
  info_.period_s = params.period_s;
  info_.offline = params.offline;
  info_.policy = policy_name(params.policy, params.abort_after);
}

Executive::~Executive() {
  if (loop_thread_.joinable()) {
    request_stop();
    go();
  }
  join();
}

void Executive::request_stop() noexcept {
  stop_requested_.store(true, std::memory_order_relaxed);
  handoff_.interrupt();  // an offline loop waiting for the dispatcher
}

void Executive::wait_finished(std::int64_t timeout_ns) noexcept {
  const std::uint32_t key = finished_event_.prepare_wait();
  if (finished()) {
    finished_event_.cancel_wait();
    return;
  }
  finished_event_.wait(key, timeout_ns);
}

void Executive::read_io_counters(io::IoCounters& sum) const noexcept {
  sum = io::IoCounters{};
  for (const io::CycleIo* a : io_) {
    io::IoCounters c{};
    a->read_counters(c);
    sum += c;
  }
}

/// The loop's time at the cycle's deadline; lock-step: the simulated periods (the waits are the
/// bench's time).
std::int64_t Executive::elapsed_ns(const LoopState& loop) const noexcept {
  if (params_.lockstep) return static_cast<std::int64_t>(loop.cycle + 1) * period_ns_;
  return loop.deadline_ns - start_ns_;
}

StopReason Executive::run_loop() {
  start_ns_ = clock_.now_ns();
  fill_report();  // the initial state: what the first cycle's events see as the last step
  LoopState loop{start_ns_ + period_ns_, 0};
  const std::int64_t duration_ns = to_ns(params_.duration_s);
  StopReason reason = StopReason::kNone;
  while (reason == StopReason::kNone) {
    if (stop_requested_.load(std::memory_order_relaxed)) {
      reason = StopReason::kRequested;
    } else if (duration_ns > 0 && elapsed_ns(loop) > duration_ns) {
      reason = StopReason::kDuration;
    } else {
      reason = cycle(loop);
    }
  }
  finish(reason);
  return reason;
}

StopReason Executive::cycle(LoopState& loop) noexcept {
  clock_.sleep_until(loop.deadline_ns);
  io::CycleTiming t{};
  t.cycle = loop.cycle;
  t.deadline_ns = loop.deadline_ns;
  t.wake_ns = clock_.now_ns();
  t.lateness_ns = t.wake_ns - t.deadline_ns;
  // lock-step: the adapters run on the loop's grid (their timeouts and send grids count
  // simulated periods, as the model does), whatever the waits took
  const std::int64_t io_ns =
      params_.lockstep ? start_ns_ + static_cast<std::int64_t>(loop.cycle + 1) * period_ns_
                       : t.wake_ns;
  if (params_.lockstep) wait_lockstep(loop, t, io_ns);
  PhaseTimer phases(clock_, t);

  for (io::CycleIo* a : io_) a->receive(io_ns, signals_);
  log_io_events(t.wake_ns);
  phases.end(io::Phase::kInputs);
  if (driver_ != nullptr) driver_->update(model_.time_s(), signals_);
  const bool event_stop = events_ != nullptr && run_events();
  phases.end(io::Phase::kDriver);
  if (params_.stall_ms > 0 && loop.cycle == params_.stall_cycle) sleep_ms(params_.stall_ms);
  const model::StepStatus status = step_model();
  fill_report();
  const std::int64_t model_end_ns = phases.end(io::Phase::kModel);
  const io::signals::CycleView view{signals_, report_};
  for (io::CycleIo* a : io_) a->transmit(params_.lockstep ? io_ns : model_end_ns, view);
  note_cycle_frames(loop.cycle, model_end_ns);
  phases.end(io::Phase::kOutputs);
  t.sim_time_s = model_.time_s();

  std::int64_t end_ns = 0;
  const OverrunDecision decision = handoff(t, phases, end_ns);
  record(t, decision, end_ns);
  loop.deadline_ns = decision.next_deadline_ns;
  cycles_.store(++loop.cycle, std::memory_order_release);
  if (hook_ != nullptr) hook_->on_cycle(loop.cycle);

  if (status != model::StepStatus::kOk) {
    if (const StopReason r = after_fault(status, t, end_ns); r != StopReason::kNone) return r;
  }
  if (decision.action == OverrunAction::kAbort) return StopReason::kAbortAfter;
  return event_stop ? StopReason::kEvent : StopReason::kNone;
}

/// The scenario events after the driver, on the last step's outputs; each one fired is logged
/// (the log is a ring: no I/O here). True if one asked to stop.
bool Executive::run_events() noexcept {
  const double t_s = model_.time_s();
  const bool stop = events_->update(t_s, io::signals::CycleView{signals_, report_}, signals_);
  for (const std::size_t i : events_->fired()) {
    const driver::EventSpec& e = events_->specs()[i];
    char detail[320];
    std::snprintf(detail, sizeof detail, "'%s' at t = %.6f s: %s %s %g held %g s; %s",
                  e.name.c_str(), t_s, e.when.signal_name.c_str(),
                  driver::compare_op_name(e.when.op), e.when.value, e.when.for_s,
                  e.stop ? "stop" : "set");
    log_.event(clock_.realtime_ns(), clock_.now_ns(), "scenario_event", detail);
  }
  return stop;
}

/// Lock-step: waits for a received cycle frame (the adapters that have cycle frames). The wait
/// is the bench's time, not the loop's: the cycle's deadline moves to its end, so neither the
/// lateness nor the overrun policy sees it (the summary's "cycle_frames" does).
void Executive::wait_lockstep(LoopState& loop, io::CycleTiming& t, std::int64_t io_ns) noexcept {
  bool waited = false, timed_out = false;
  for (io::CycleIo* a : io_) {
    const io::CycleFrameWait w = a->wait_cycle_frame(io_ns, params_.lockstep_timeout_ns);
    waited = waited || w != io::CycleFrameWait::kNoCycleFrames;
    timed_out = timed_out || w == io::CycleFrameWait::kTimeout;
  }
  if (!waited) return;
  const std::int64_t now_ns = clock_.now_ns();
  ++cycle_frames_.lockstep_waits;
  const auto wait_ns = static_cast<std::uint64_t>(now_ns - t.wake_ns);
  if (wait_ns > cycle_frames_.lockstep_wait_max_ns) cycle_frames_.lockstep_wait_max_ns = wait_ns;
  if (timed_out) {
    ++cycle_frames_.lockstep_timeouts;
    char detail[160];
    std::snprintf(detail, sizeof detail,
                  "cycle %llu: no cycle frame within %.0f ms; the cycle runs on the held inputs",
                  static_cast<unsigned long long>(t.cycle),
                  static_cast<double>(params_.lockstep_timeout_ns) * 1e-6);
    log_.event(clock_.realtime_ns(), now_ns, "lockstep_timeout", detail);
  }
  if (now_ns > loop.deadline_ns) loop.deadline_ns = now_ns;
  t.deadline_ns = loop.deadline_ns;
  t.wake_ns = now_ns;
  t.lateness_ns = 0;
}

/// The cycle numbers of the answers: a received cycle frame (rx cycle) is answered by the
/// first cycle frame sent from that cycle on (tx cycle).
void Executive::note_cycle_frames(std::uint64_t cycle, std::int64_t now_ns) noexcept {
  bool received = false, sent = false;
  for (const io::CycleIo* a : io_) {
    received = received || a->cycle_frame_received();
    sent = sent || a->cycle_frame_sent();
  }
  const auto c = static_cast<std::int64_t>(cycle);
  if (received) {
    ++cycle_frames_.received;
    if (pending_rx_cycle_ < 0) pending_rx_cycle_ = c;  // the oldest unanswered one
  }
  if (!sent || pending_rx_cycle_ < 0) return;
  const std::int64_t lag = c - pending_rx_cycle_;
  cycle_frames_.last_rx_cycle = pending_rx_cycle_;
  cycle_frames_.last_tx_cycle = c;
  if (lag == 0) {
    ++cycle_frames_.answered_same_cycle;
  } else if (lag == 1) {
    ++cycle_frames_.answered_next_cycle;
  } else {
    ++cycle_frames_.answered_later;
    char detail[160];
    std::snprintf(detail, sizeof detail,
                  "the cycle frame received in cycle %lld was answered in cycle %lld",
                  static_cast<long long>(pending_rx_cycle_), static_cast<long long>(c));
    log_.event(clock_.realtime_ns(), now_ns, "late_answer", detail);
  }
  // a frame received in this cycle is answered by this cycle's send
  pending_rx_cycle_ = -1;
}

/// The adapters' events (bus state changes, rate-limited reports) into the event log.
void Executive::log_io_events(std::int64_t now_ns) noexcept {
  io::IoEvent e;
  for (io::CycleIo* a : io_) {
    while (a->next_event(e))
      log_.event(clock_.realtime_ns(), now_ns, e.name.data(), e.detail.data());
  }
}

/// The model phase: one step, unless a held fault froze the model. On a vehicle fault the
/// model is at its last fault-free state and wrote no output: the outputs are flagged invalid
/// (CAN sends a mapped `invalid` raw value, else the last valid one) for as long as it lasts.
model::StepStatus Executive::step_model() noexcept {
  if (held_) return model::StepStatus::kOk;
  const model::StepStatus status = model_.step(signals_);
  if (status == model::StepStatus::kOk) return status;
  const model::ModelFault f = model_.last_fault();
  if (f.kind == model::FaultKind::kNone) return status;  // no fault report (the quarter car)
  fault_ = f;
  for (std::size_t i = model::index(model::kFirstOutput); i < model::kSignalCount; ++i)
    signals_.valid[i] = false;
  held_ = params_.hold_on_vehicle_fault;
  return model::StepStatus::kVehicleFault;
}

/// The cycle's report with its validity (the model's state, or after a fault its last
/// fault-free one, flagged invalid).
void Executive::fill_report() noexcept {
  model_.fill_report(report_);
  report_.valid = fault_.kind == model::FaultKind::kNone ? 1 : 0;
  report_.fault_kind = static_cast<std::int32_t>(fault_.kind);
  report_.fault_unit = fault_.kind == model::FaultKind::kNone ? -1 : fault_.unit;
}

/// The event of a failed step, and whether the loop stops.
StopReason Executive::after_fault(model::StepStatus status, const io::CycleTiming& t,
                                  std::int64_t end_ns) noexcept {
  char detail[400];
  if (status == model::StepStatus::kVehicleFault) {
    format_vehicle_fault(fault_, fault_unit_file().c_str(), detail, sizeof detail);
    const std::size_t n = std::char_traits<char>::length(detail);
    std::snprintf(detail + n, sizeof detail - n, "; %s", held_ ? "holding" : "stopping");
    log_.event(clock_.realtime_ns(), end_ns, "vehicle_fault", detail);
    return held_ ? StopReason::kNone : StopReason::kVehicleFault;
  }
  std::snprintf(detail, sizeof detail,
                "model step produced a non-finite value at cycle %llu, t = %.6f s; stopping",
                static_cast<unsigned long long>(t.cycle), t.sim_time_s);
  log_.event(clock_.realtime_ns(), end_ns, "non_finite", detail);
  return StopReason::kNonFinite;
}

const std::string& Executive::fault_unit_file() const noexcept {
  static const std::string kNone;
  const auto u = static_cast<std::size_t>(fault_.unit);
  return fault_.unit >= 0 && u < params_.unit_files.size() ? params_.unit_files[u] : kNone;
}

/// The handoff phase: fills a snapshot, ends the phase, decides on the overrun once (so that the
/// snapshot carries the same decision as the log and the statistics) and commits.
OverrunDecision Executive::handoff(io::CycleTiming& t, PhaseTimer& phases,
                                   std::int64_t& end_ns) noexcept {
  io::Snapshot* slot = handoff_.claim(stop_requested_);
  if (slot != nullptr) {
    slot->signals = signals_;
    copy_report(report_, slot->report);
    read_io_counters(slot->can);
  }
  end_ns = phases.end(io::Phase::kHandoff);
  t.compute_ns = end_ns - t.wake_ns;
  const OverrunDecision decision =
      decide(overrun_, t.deadline_ns, end_ns, period_ns_, consecutive_misses_);
  consecutive_misses_ = decision.consecutive_misses;
  t.deadline_miss = decision.miss();
  t.consecutive_misses = decision.consecutive_misses;
  if (slot != nullptr) {
    slot->timing = t;
    handoff_.commit();
  }
  return decision;
}

/// Statistics and the overrun log line (no I/O: the log is a ring).
void Executive::record(const io::CycleTiming& t, const OverrunDecision& decision,
                       std::int64_t end_ns) noexcept {
  lateness_.add(t.lateness_ns);
  compute_.add(t.compute_ns);
  for (std::size_t p = 0; p < io::kPhaseCount; ++p) phases_[p].add(t.phase_ns[p]);
  sim_time_s_.store(t.sim_time_s, std::memory_order_relaxed);
  loop_time_s_.store(static_cast<double>(end_ns - start_ns_) * 1e-9, std::memory_order_relaxed);
  if (!decision.miss()) return;
  misses_.fetch_add(1, std::memory_order_relaxed);
  skipped_.fetch_add(static_cast<std::uint64_t>(decision.skipped_periods),
                     std::memory_order_relaxed);
  std::array<char, 24> action{};
  format_action(decision, action);
  log_.miss(clock_.realtime_ns(), end_ns, t, action.data());
}

void Executive::finish(StopReason reason) noexcept {
  reason_ = reason;
  handoff_.close();
  finished_event_.notify();
}

void Executive::apply_rt_settings() {
  // The outcome goes into info_ before rt_ready_; the caller warns once.
  std::string problems;
  const auto note = [&problems](const rt::SetupResult& r) {
    if (r.ok) return;
    problems += problems.empty() ? "" : "; ";
    problems += r.message;
  };
  note(rt::set_timer_slack(1));
  if (!params_.offline) {
    const rt::SetupResult fifo = rt::set_sched_fifo(params_.priority);
    info_.sched_fifo = fifo.ok;
    if (fifo.ok) info_.priority = params_.priority;
    note(fifo);
  }
  if (params_.cpu >= 0) {
    const rt::SetupResult pinned = rt::set_cpu_affinity(params_.cpu);
    if (pinned.ok) info_.cpu = params_.cpu;
    note(pinned);
  }
  if (!rt_problems_.empty() && !problems.empty()) rt_problems_ += "; ";
  rt_problems_ += problems;
}

void Executive::loop_thread_main() {
  apply_rt_settings();
  rt_ready_.store(true, std::memory_order_release);
  rt_ready_.notify_all();
  go_.wait(false, std::memory_order_acquire);
  if (stop_requested_.load()) {
    finish(StopReason::kRequested);
    return;
  }
  run_loop();
}

io::RunInfo Executive::prepare(const std::string& config_file) {
  info_.config_file = config_file;
  if (!params_.offline) {
    const rt::SetupResult locked = rt::lock_memory();
    info_.memory_locked = locked.ok;
    rt_problems_ = locked.message;
  }
  dispatcher_.start_sinks(info_);
  loop_thread_ = start_thread([this] { loop_thread_main(); });
  rt_ready_.wait(false, std::memory_order_acquire);
  dispatcher_.start();
  return info_;
}

void Executive::go() {
  go_.store(true, std::memory_order_release);
  go_.notify_all();
}

StopReason Executive::join() {
  if (loop_thread_.joinable()) loop_thread_.join();
  dispatcher_.join();
  return reason_;
}

}  // namespace rig
