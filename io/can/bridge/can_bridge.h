#pragma once
/// @file
/// io::CycleIo over CAN: the SocketCAN transport plus the DBC mapping's RX and TX engines.
///
/// receive(): services the transport (ENOBUFS retries, reopen while down), drains every pending
/// frame into can::mapping::RxProcessor (validation, decode, clamp, SI), applies timeouts (fallback
/// + invalid), then copies the inputs it feeds (handed at construction by the rig's routing) into
/// the model's inputs.
/// transmit(): asks can::mapping::TxScheduler for the frames due now (phase grid of each
/// GenMsgCycleTime, counter and checksum filled in) and sends them without blocking. Both are
/// allocation-free, exception-free and non-blocking. Frame times given to the RX engine are the
/// loop's monotonic cycle time (the same clock as its timeouts); kernel receive timestamps
/// (CLOCK_REALTIME) stay available to tools through the transport.
///
/// Events (next_event()): every change of the bus state (can_error_passive, can_bus_off,
/// can_bus_down, can_bus_up) and the RX engine's rate-limited out_of_range reports, which name
/// the signal, the value and the count. They wait in a fixed queue of kEventQueue; beyond that
/// they are counted in events_dropped() and the loss is reported with the next event.

#include <array>
#include <cstdint>

#include "io/can/mapping/can_mapping.h"
#include "io/can/mapping/rx_processor.h"
#include "io/can/mapping/tx_scheduler.h"
#include "io/can/transport/socket_can_transport.h"
#include "io/cycle_io.h"

namespace rig::io::can::bridge {

class CanBridge final : public io::CycleIo {
 public:
  static constexpr std::size_t kMaxFramesPerCycle = 64;  ///< TX frames encoded per cycle
  static constexpr std::size_t kEventQueue = 16;         ///< pending events at most

  /// `transport_settings.filter_ids` are filled from the RX mapping if `kernel_filter`. `feeds`:
  /// the model inputs this bridge writes (those routed to CAN).
  CanBridge(can::mapping::CanConfig config, can::transport::TransportSettings transport_settings,
            bool kernel_filter, const io::InputSet& feeds);

  void receive(std::int64_t monotonic_ns, model::Signals& inputs) noexcept override;
  void transmit(std::int64_t monotonic_ns, const signals::CycleView& cycle) noexcept override;
  void read_counters(IoCounters& counters) const noexcept override;
  bool next_event(io::IoEvent& event) noexcept override;
  void set_cycle_frames(std::int64_t period_ns) noexcept override;
  io::CycleFrameWait wait_cycle_frame(std::int64_t loop_ns,
                                      std::int64_t timeout_ns) noexcept override;
  [[nodiscard]] bool cycle_frame_received() const noexcept override { return cycle_rx_; }
  [[nodiscard]] bool cycle_frame_sent() const noexcept override { return cycle_tx_; }
  [[nodiscard]] std::uint64_t events_dropped() const noexcept { return events_dropped_; }

  [[nodiscard]] const can::transport::SocketCanTransport& transport() const noexcept {
    return transport_;
  }
  [[nodiscard]] const can::mapping::RxProcessor& rx() const noexcept { return rx_; }

 private:
  static can::transport::TransportSettings with_filter(can::transport::TransportSettings settings,
                                                       const can::mapping::CanConfig& config,
                                                       bool kernel_filter);
  void start(std::int64_t monotonic_ns) noexcept;
  /// Drains the transport into the RX engine at `monotonic_ns` (cycle frames noted).
  void drain(std::int64_t monotonic_ns) noexcept;
  /// The message's id is one of `ids` (the first `count`).
  static bool is_cycle_frame(const std::array<std::uint32_t, 8>& ids, std::size_t count,
                             std::uint32_t id) noexcept;
  void watch_bus_state() noexcept;
  void report_out_of_range(const can::mapping::OutOfRangeReport& r) noexcept;
  /// Queues an event (printf-style detail); counts it as dropped if the queue is full.
  void push_event(const char* name, const char* format, ...) noexcept
      __attribute__((format(printf, 3, 4)));

  can::mapping::CanConfig config_;
  can::mapping::RxProcessor rx_;
  can::mapping::TxScheduler tx_;
  can::transport::SocketCanTransport transport_;
  io::InputSet feeds_;
  bool started_ = false;
  model::Signals rx_signals_{};  // what the RX engine writes; the fed inputs are copied out
  IoCounters engine_counters_{};
  std::array<can::mapping::TxFrame, kMaxFramesPerCycle> tx_frames_{};
  io::BusState last_state_ = io::BusState::kUp;
  std::array<io::IoEvent, kEventQueue> events_{};
  std::size_t event_head_ = 0;
  std::size_t event_count_ = 0;
  std::uint64_t events_dropped_ = 0;
  std::uint64_t drops_reported_ = 0;
  // cycle frames (set_cycle_frames): their ids, and whether this cycle took one in / sent one
  std::array<std::uint32_t, 8> cycle_rx_ids_{};
  std::size_t cycle_rx_count_ = 0;
  std::array<std::uint32_t, 8> cycle_tx_ids_{};
  std::size_t cycle_tx_count_ = 0;
  bool cycle_rx_ = false;
  bool cycle_rx_pending_ = false;  // taken in by wait_cycle_frame(), reported by receive()
  bool cycle_tx_ = false;
};

}  // namespace rig::io::can::bridge
