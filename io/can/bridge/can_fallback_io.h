#pragma once
/// @file
/// The CAN inputs while CAN is switched off (`rig run --can none` on a configuration with
/// [can]): each input routed to CAN holds its mapping's `fallback`, flagged invalid, as after a
/// timeout. Nothing is received or sent; the bus state stays "disabled".

#include <utility>
#include <vector>

#include "io/cycle_io.h"

namespace rig::io::can::bridge {

class CanFallbackIo final : public io::CycleIo {
 public:
  struct Fallback {
    std::size_t slot = 0;  ///< the input slot
    double value = 0.0;
  };
  explicit CanFallbackIo(std::vector<Fallback> fallbacks) : fallbacks_(std::move(fallbacks)) {}

  void receive(std::int64_t /*monotonic_ns*/, model::Signals& inputs) noexcept override {
    for (const Fallback& f : fallbacks_) {
      inputs.value[f.slot] = f.value;
      inputs.valid[f.slot] = false;
    }
  }
  void transmit(std::int64_t /*monotonic_ns*/,
                const signals::CycleView& /*cycle*/) noexcept override {}
  void read_counters(IoCounters& counters) const noexcept override { counters = IoCounters{}; }

 private:
  std::vector<Fallback> fallbacks_;
};

}  // namespace rig::io::can::bridge
