#pragma once
/// @file
/// The ENOBUFS rule of the transport, as a small fixed-capacity queue.
///
/// Rule: a frame the kernel refuses for lack of buffer space (ENOBUFS, or EAGAIN when the socket
/// send buffer is full) is counted and kept for exactly ONE retry at the start of the next cycle,
/// before that cycle's new frames (so the order on the bus is kept). If the retry is refused too,
/// or the queue is already full when a frame is refused, the frame is dropped and counted. A
/// periodic signal is thus never more than one cycle late, and a congested bus never builds an
/// unbounded backlog of stale values.

#include <array>
#include <cstddef>

#include "io/can/transport/transport_frame.h"

namespace rig::io::can::transport {

class SendRetryQueue {
 public:
  static constexpr std::size_t kCapacity = 32;

  /// Keeps `frame` for the next retry. False (frame not kept) if the queue is full.
  bool push(const TransportFrame& frame) noexcept {
    if (size_ == kCapacity) return false;
    frames_[size_++] = frame;
    return true;
  }

  /// Offers every kept frame once to `try_send` (bool(const TransportFrame&), true = accepted),
  /// oldest first, and empties the queue. Returns how many were refused (to be counted dropped).
  template <class TrySend>
  std::size_t retry_all(TrySend&& try_send) noexcept {
    std::size_t refused = 0;
    for (std::size_t i = 0; i < size_; ++i) {
      if (!try_send(frames_[i])) ++refused;
    }
    size_ = 0;
    return refused;
  }

  /// Forgets everything (the bus went down); returns how many frames were forgotten.
  std::size_t clear() noexcept {
    const std::size_t n = size_;
    size_ = 0;
    return n;
  }

  [[nodiscard]] std::size_t size() const noexcept { return size_; }

 private:
  std::array<TransportFrame, kCapacity> frames_{};
  std::size_t size_ = 0;
};

}  // namespace rig::io::can::transport
