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

  /// `transport_settings.filter_ids` are filled from the RX mapping if `kernel_filter`. `feeds`:
  /// the model inputs this bridge writes (those routed to CAN).
  CanBridge(can::mapping::CanConfig config, can::transport::TransportSettings transport_settings,
            bool kernel_filter, const io::InputSet& feeds);

  void receive(std::int64_t monotonic_ns, model::Signals& inputs) noexcept override;
  void transmit(std::int64_t monotonic_ns, const model::Signals& outputs) noexcept override;
  void read_counters(IoCounters& counters) const noexcept override;

  [[nodiscard]] const can::transport::SocketCanTransport& transport() const noexcept {
    return transport_;
  }
  [[nodiscard]] const can::mapping::RxProcessor& rx() const noexcept { return rx_; }

 private:
  static can::transport::TransportSettings with_filter(can::transport::TransportSettings settings,
                                                       const can::mapping::CanConfig& config,
                                                       bool kernel_filter);
  void start(std::int64_t monotonic_ns) noexcept;

  can::mapping::CanConfig config_;
  can::mapping::RxProcessor rx_;
  can::mapping::TxScheduler tx_;
  can::transport::SocketCanTransport transport_;
  io::InputSet feeds_;
  bool started_ = false;
  model::Signals rx_signals_{};  // what the RX engine writes; the fed inputs are copied out
  IoCounters engine_counters_{};
  std::array<can::mapping::TxFrame, kMaxFramesPerCycle> tx_frames_{};
};

}  // namespace rig::io::can::bridge
