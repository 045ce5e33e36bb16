#include "io/can/bridge/can_bridge.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <span>
#include <utility>

#include <poll.h>

namespace rig::io::can::bridge {

can::transport::TransportSettings CanBridge::with_filter(can::transport::TransportSettings settings,
                                                         const can::mapping::CanConfig& config,
                                                         bool kernel_filter) {
  settings.use_filter = kernel_filter;
  settings.filter_ids.clear();
  settings.extended_filter_ids.clear();
  if (kernel_filter) {
    for (const auto& binding : config.mapping.rx) {
      const auto& message = config.database.messages[binding.dbc_message];
      (message.extended ? settings.extended_filter_ids : settings.filter_ids).push_back(message.id);
    }
  }
  return settings;
}

CanBridge::CanBridge(can::mapping::CanConfig config,
                     can::transport::TransportSettings transport_settings, bool kernel_filter,
                     const io::InputSet& feeds)
    : config_(std::move(config)),
      rx_(config_),
      tx_(config_),
      transport_(with_filter(std::move(transport_settings), config_, kernel_filter)),
      feeds_(feeds) {}

void CanBridge::start(std::int64_t monotonic_ns) noexcept {
  rx_.reset(monotonic_ns, rx_signals_);
  tx_.start(monotonic_ns);
  last_state_ = transport_.state();
  started_ = true;
}

void CanBridge::push_event(const char* name, const char* format, ...) noexcept {
  if (event_count_ == events_.size()) {
    ++events_dropped_;
    return;
  }
  io::IoEvent& e = events_[(event_head_ + event_count_) % events_.size()];
  std::snprintf(e.name.data(), e.name.size(), "%s", name);
  std::va_list args;
  va_start(args, format);
  std::vsnprintf(e.detail.data(), e.detail.size(), format, args);
  va_end(args);
  ++event_count_;
}

bool CanBridge::next_event(io::IoEvent& event) noexcept {
  if (event_count_ == 0) return false;
  event = events_[event_head_];
  event_head_ = (event_head_ + 1) % events_.size();
  --event_count_;
  if (events_dropped_ != drops_reported_) {
    const std::size_t n = std::strlen(event.detail.data());
    std::snprintf(event.detail.data() + n, event.detail.size() - n, " (%llu CAN events lost)",
                  static_cast<unsigned long long>(events_dropped_ - drops_reported_));
    drops_reported_ = events_dropped_;
  }
  return true;
}

/// One event per change of the bus state (error frames, bus-off, restart, link down/up).
void CanBridge::watch_bus_state() noexcept {
  const io::BusState now = transport_.state();
  if (now == last_state_) return;
  const char* name = "can_bus_up";
  if (now == io::BusState::kErrorPassive) name = "can_error_passive";
  if (now == io::BusState::kBusOff) name = "can_bus_off";
  if (now == io::BusState::kDown) name = "can_bus_down";
  push_event(name, "%s: bus %s -> %s (error frames %llu, last class 0x%03x, controller 0x%02x)",
             transport_.settings().interface.c_str(), io::bus_state_name(last_state_),
             io::bus_state_name(now),
             static_cast<unsigned long long>(transport_.counters().error_frames),
             static_cast<unsigned>(transport_.last_error_class()),
             static_cast<unsigned>(transport_.last_error_controller()));
  last_state_ = now;
}

void CanBridge::report_out_of_range(const can::mapping::OutOfRangeReport& r) noexcept {
  const auto count = static_cast<unsigned long long>(r.count);
  if (!std::isfinite(r.received) && std::strcmp(r.direction, "rx") == 0) {
    push_event("out_of_range",
               "rx %s.%s: %g is not finite, previous value kept; %llu since the last report",
               r.message, r.signal, r.received, count);
    return;
  }
  // As the engines clamp: beyond the maximum to it, everything else (below, NaN) to the minimum.
  const double clamped = r.received > r.maximum ? r.maximum : r.minimum;
  push_event("out_of_range",
             "%s %s.%s: %g outside [%g, %g], clamped to %g; %llu since the last report",
             r.direction, r.message, r.signal, r.received, r.minimum, r.maximum, clamped, count);
}

namespace {

std::uint32_t key(std::uint32_t id, bool extended) noexcept {
  return extended ? (id | 0x80000000u) : id;
}

std::int64_t monotonic_now_ns() noexcept {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

}  // namespace

bool CanBridge::is_cycle_frame(const std::array<std::uint32_t, 8>& ids, std::size_t count,
                               std::uint32_t id) noexcept {
  for (std::size_t i = 0; i < count; ++i)
    if (ids[i] == id) return true;
  return false;
}

void CanBridge::set_cycle_frames(std::int64_t period_ns) noexcept {
  cycle_rx_count_ = cycle_tx_count_ = 0;
  const auto cyclic = [&](const can::mapping::MessageBinding& b) {
    const auto& m = config_.database.messages[b.dbc_message];
    return m.cycle_time_ms > 0 &&
           static_cast<std::int64_t>(m.cycle_time_ms) * 1'000'000 <= period_ns;
  };
  for (const auto& b : config_.mapping.rx) {
    if (cycle_rx_count_ < cycle_rx_ids_.size() && cyclic(b))
      cycle_rx_ids_[cycle_rx_count_++] = config_.database.messages[b.dbc_message].dbc_id();
  }
  for (const auto& b : config_.mapping.tx) {
    if (cycle_tx_count_ < cycle_tx_ids_.size() && cyclic(b))
      cycle_tx_ids_[cycle_tx_count_++] = config_.database.messages[b.dbc_message].dbc_id();
  }
}

void CanBridge::drain(std::int64_t monotonic_ns) noexcept {
  transport_.drain([&](const can::transport::TransportFrame& f) {
    using can::mapping::FrameFormat;
    const FrameFormat format =
        f.remote ? FrameFormat::kRemote : (f.fd ? FrameFormat::kFd : FrameFormat::kClassic);
    rx_.on_frame(f.id, f.extended, format, f.data.data(), f.len, monotonic_ns, rx_signals_,
                 engine_counters_);
    if (is_cycle_frame(cycle_rx_ids_, cycle_rx_count_, key(f.id, f.extended)))
      cycle_rx_pending_ = true;
  });
}

io::CycleFrameWait CanBridge::wait_cycle_frame(std::int64_t loop_ns,
                                               std::int64_t timeout_ns) noexcept {
  if (cycle_rx_count_ == 0) return io::CycleFrameWait::kNoCycleFrames;
  if (!started_) start(loop_ns);
  const std::int64_t start_ns = monotonic_now_ns();
  for (;;) {
    const std::int64_t now_ns = monotonic_now_ns();
    transport_.service(loop_ns);
    drain(loop_ns);
    if (cycle_rx_pending_) return io::CycleFrameWait::kReceived;
    const std::int64_t left_ns = start_ns + timeout_ns - now_ns;
    if (left_ns <= 0) return io::CycleFrameWait::kTimeout;
    pollfd p{transport_.fd(), POLLIN, 0};
    const int ms = static_cast<int>((left_ns + 999'999) / 1'000'000);
    if (p.fd < 0) {  // the interface is down: wait for its reopen (service) a little later
      const timespec ts{0, 1'000'000};
      nanosleep(&ts, nullptr);
    } else {
      (void)poll(&p, 1, ms);
    }
  }
}

void CanBridge::receive(std::int64_t monotonic_ns, model::Signals& inputs) noexcept {
  if (!started_) start(monotonic_ns);
  transport_.service(monotonic_ns);
  drain(monotonic_ns);
  cycle_rx_ = cycle_rx_pending_;
  cycle_rx_pending_ = false;
  rx_.check_timeouts(monotonic_ns, rx_signals_, engine_counters_);
  watch_bus_state();
  rx_.take_out_of_range_reports(
      monotonic_ns, [this](const can::mapping::OutOfRangeReport& r) { report_out_of_range(r); });
  for (std::size_t i = 0; i < model::kSlotCount; ++i) {
    if (!feeds_[i]) continue;  // inputs only: the routing feeds no output
    inputs.value[i] = rx_signals_.value[i];
    inputs.valid[i] = rx_signals_.valid[i];
  }
}

void CanBridge::transmit(std::int64_t monotonic_ns, const signals::CycleView& cycle) noexcept {
  if (!started_) start(monotonic_ns);
  const std::size_t n = tx_.due_frames(
      monotonic_ns, cycle, std::span<can::mapping::TxFrame>(tx_frames_), engine_counters_);
  tx_.take_out_of_range_reports(
      monotonic_ns, [this](const can::mapping::OutOfRangeReport& r) { report_out_of_range(r); });
  cycle_tx_ = false;
  for (std::size_t i = 0; i < n; ++i) {
    const can::mapping::TxFrame& in = tx_frames_[i];
    if (is_cycle_frame(cycle_tx_ids_, cycle_tx_count_, key(in.id, in.extended))) cycle_tx_ = true;
    can::transport::TransportFrame out;
    out.id = in.id;
    out.extended = in.extended;
    out.fd = in.fd;
    out.len = in.len;
    std::memcpy(out.data.data(), in.data.data(), in.len);
    transport_.send(out);
  }
}

void CanBridge::read_counters(IoCounters& counters) const noexcept {
  counters = engine_counters_;  // timeouts, checksum/counter failures, bad/unknown, out_of_range
  const can::transport::TransportCounters& t = transport_.counters();
  counters.bus_state = transport_.state();
  counters.frames_received = t.frames_received;
  counters.rx_overflows = t.rx_overflows;
  counters.frames_sent = t.frames_sent;
  counters.error_frames = t.error_frames;
  counters.bad_frames += t.malformed;
  counters.send_no_buffer = t.send_no_buffer;
  counters.send_dropped = t.send_dropped;
  counters.reopens = t.reopens;
}

}  // namespace rig::io::can::bridge
