#pragma once
/// @file
/// The interface the executive's loop calls on each I/O adapter (CAN, ...) once per cycle.

#include <array>
#include <bitset>
#include <cstdint>

#include "io/io_counters.h"
#include "io/signals/binding.h"
#include "model/signals.h"

namespace rig::io {

/// A set of model inputs (bit: the input slot, model::index(signal) or a unit block slot), e.g.
/// those an adapter feeds. Decided once at start (the rig's routing) and handed to each adapter at
/// construction.
using InputSet = std::bitset<model::kSlotCount>;

/// Something an adapter wants in the event log (a bus state change, a rate-limited report):
/// plain data, fixed size (the sizes of the log's records, io/log/log_record.h).
struct IoEvent {
  std::array<char, 24> name{};     ///< e.g. "can_bus_off"
  std::array<char, 160> detail{};  ///< free text
};

/// What a lock-step wait (CycleIo::wait_cycle_frame) found.
enum class CycleFrameWait { kNoCycleFrames, kReceived, kTimeout };

/// An adapter that exchanges model signals with the outside once per cycle. Both calls run on
/// the RT thread: non-blocking, allocation-free, no exceptions. Failures are counted, never fatal.
class CycleIo {
 public:
  CycleIo() = default;
  CycleIo(const CycleIo&) = delete;
  CycleIo& operator=(const CycleIo&) = delete;
  virtual ~CycleIo() = default;

  /// Inputs phase: drains everything pending and writes the inputs this adapter feeds (the set
  /// it was constructed with), marking stale ones invalid with their fallback value.
  virtual void receive(std::int64_t monotonic_ns, model::Signals& inputs) noexcept = 0;
  /// Outputs phase: encodes and sends what is due at this time, reading the cycle's signals and
  /// the report the executive filled after the step (through catalogue bindings).
  virtual void transmit(std::int64_t monotonic_ns, const signals::CycleView& cycle) noexcept = 0;
  /// Current counters, copied into the cycle's snapshot.
  virtual void read_counters(IoCounters& counters) const noexcept = 0;
  /// Hands over the oldest pending event (false: none). The loop calls it after receive()
  /// until it returns false and writes each into the event log.
  virtual bool next_event(IoEvent& event) noexcept {
    (void)event;
    return false;
  }

  // ---- cycle frames (issue 15: rack-in-the-loop, rig run --lockstep; docs/can.md) ----
  /// Called once at construction of the loop: the adapter's messages with a cycle time of at
  /// most `period_ns` (received and sent) are its cycle frames. Default: none.
  virtual void set_cycle_frames(std::int64_t period_ns) noexcept { (void)period_ns; }
  /// Lock-step: blocks (the only blocking call, and only with --lockstep) until a received cycle
  /// frame is pending or was taken in since the last receive(), at most `timeout_ns` of real
  /// time; frames taken in are stamped `loop_ns` (the loop's time of the cycle).
  virtual CycleFrameWait wait_cycle_frame(std::int64_t loop_ns, std::int64_t timeout_ns) noexcept {
    (void)loop_ns;
    (void)timeout_ns;
    return CycleFrameWait::kNoCycleFrames;
  }
  /// After receive(): whether it took in a received cycle frame; after transmit(): whether it
  /// sent one.
  [[nodiscard]] virtual bool cycle_frame_received() const noexcept { return false; }
  [[nodiscard]] virtual bool cycle_frame_sent() const noexcept { return false; }
};

}  // namespace rig::io
