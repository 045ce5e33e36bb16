#pragma once
/// @file
/// A raw SocketCAN socket (classic and FD) bound to one interface, for the RT loop.
///
/// - Non-blocking throughout. drain() reads every pending frame with recvmmsg() in batches, with
///   kernel receive timestamps (SO_TIMESTAMPNS), kernel drop counts (SO_RXQ_OVFL), error frames
///   enabled (CAN_RAW_ERR_FILTER = all classes) and counted, never handed over.
/// - send() never blocks (MSG_DONTWAIT); ENOBUFS follows the rule of SendRetryQueue.
/// - Error frames set the controller state: bus-off (CAN_ERR_BUSOFF) until a restart
///   (CAN_ERR_RESTARTED); any other error frame error-passive until the controller reports
///   error-active again (CAN_ERR_CRTL_ACTIVE) or restarts. state() gives the worse of that and
///   the link state.
/// - ENETDOWN / ENODEV from any call flags the bus down (io::BusState::kDown); sends are then
///   dropped and counted. service() tries to reopen at most every `reopen_interval_ns`: a new
///   socket, SIOCGIFFLAGS (still down -> stay down), SIOCGIFINDEX, the socket options, bind.
///   These are plain system calls on stack buffers and a filter array sized at construction, so
///   reopening runs on the RT thread without allocation (a few microseconds, at a bounded rate).
/// - The constructor (load time) throws TransportError with a clear message if the kernel has no
///   AF_CAN, or the interface does not exist or is not a CAN interface.
/// Nothing after construction allocates.

#include <linux/can.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "io/can/transport/send_retry_queue.h"
#include "io/can/transport/transport_counters.h"
#include "io/can/transport/transport_error.h"
#include "io/can/transport/transport_frame.h"
#include "io/can/transport/transport_settings.h"
#include "io/io_counters.h"

namespace rig::io::can::transport {

/// Outcome of one send().
enum class SendStatus : std::uint8_t {
  kSent,      ///< accepted by the kernel
  kDeferred,  ///< no buffer space: kept for one retry next cycle
  kDropped,   ///< given up (queue full, bus down, frame invalid for the interface)
};

class SocketCanTransport {
 public:
  static constexpr std::size_t kBatch = 32;  ///< frames per recvmmsg() call

  /// Opens and binds the socket. Throws TransportError (load time only).
  explicit SocketCanTransport(TransportSettings settings);
  ~SocketCanTransport();
  SocketCanTransport(const SocketCanTransport&) = delete;
  SocketCanTransport& operator=(const SocketCanTransport&) = delete;

  /// Once per cycle, before drain() and send(): retries deferred frames (ENOBUFS rule) and, while
  /// the bus is down, reopens at the bounded rate.
  void service(std::int64_t monotonic_ns) noexcept;

  /// Hands every pending data frame to `visit(const TransportFrame&)`, at most
  /// `max_frames_per_drain` per call (the rest stays queued in the kernel for the next cycle).
  /// Returns the number of frames handed over.
  template <class Visitor>
  std::size_t drain(Visitor&& visit) noexcept {
    std::size_t total = 0;
    while (total < settings_.max_frames_per_drain) {
      std::size_t got = 0;
      const bool more = read_batch(got);
      for (std::size_t i = 0; i < got; ++i) visit(batch_[i]);
      total += got;
      if (!more) break;
    }
    return total;
  }

  /// Sends one frame without blocking.
  SendStatus send(const TransportFrame& frame) noexcept;

  /// The link state (up/down) combined with the controller's error state (error-passive,
  /// bus-off): the worse of both.
  [[nodiscard]] BusState state() const noexcept {
    return state_ == BusState::kUp ? controller_ : state_;
  }
  /// The class bits of the last error frame (can_id & CAN_ERR_MASK) and its data[1] (controller
  /// status), 0 before the first.
  [[nodiscard]] std::uint32_t last_error_class() const noexcept { return last_error_class_; }
  [[nodiscard]] std::uint8_t last_error_controller() const noexcept { return last_error_ctrl_; }
  /// Whether the interface carries CAN FD frames (its MTU is CANFD_MTU), read at construction.
  [[nodiscard]] bool fd_capable() const noexcept { return fd_capable_; }
  [[nodiscard]] const TransportCounters& counters() const noexcept { return counters_; }
  [[nodiscard]] const TransportSettings& settings() const noexcept { return settings_; }
  /// The socket, for poll() in tests and tools; -1 while down.
  [[nodiscard]] int fd() const noexcept { return fd_; }

 private:
  /// Reads up to kBatch frames into batch_; `got` = data frames stored. Returns true if the
  /// batch was full (more may be pending).
  bool read_batch(std::size_t& got) noexcept;
  /// Opens, configures and binds a socket; returns the fd or -errno (never throws).
  int open_socket() noexcept;
  enum class Raw : std::uint8_t { kSent, kNoBuffer, kDown, kInvalid };
  Raw send_now(const TransportFrame& frame) noexcept;
  void go_down() noexcept;
  void on_error_frame(const ::canfd_frame& frame) noexcept;

  TransportSettings settings_;
  std::vector<::can_filter> filters_;  // sized once at construction
  int fd_ = -1;
  BusState state_ = BusState::kDown;     // link: kUp or kDown
  BusState controller_ = BusState::kUp;  // kUp, kErrorPassive or kBusOff
  std::uint32_t last_error_class_ = 0;
  std::uint8_t last_error_ctrl_ = 0;
  bool fd_capable_ = false;
  std::int64_t next_reopen_ns_ = 0;
  std::uint32_t last_overflow_ = 0;  // SO_RXQ_OVFL is cumulative per socket
  TransportCounters counters_;
  SendRetryQueue retry_;
  std::array<TransportFrame, kBatch> batch_{};
  struct RecvBuffers;
  std::unique_ptr<RecvBuffers> rx_;  // allocated at construction (keeps <sys/socket.h> out)
};

/// Whether this kernel offers AF_CAN raw sockets; on false, `why` says what failed.
bool can_sockets_available(std::string* why = nullptr);

}  // namespace rig::io::can::transport
