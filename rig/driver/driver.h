#pragma once
/// @file
/// The driver phase of a cycle: fills the inputs that no ECU provides.

#include "io/cycle_io.h"
#include "model/signals.h"

namespace rig::driver {

/// A source of driver inputs: an open-loop maneuver table, a closed-loop driver, ... Runs on the
/// RT thread after the inputs phase: no allocation, no blocking, no exceptions.
class Driver {
 public:
  /// `feeds`: the inputs this driver writes (the routing's decision, rig/routing.h).
  explicit Driver(const io::InputSet& feeds) : feeds_(feeds) {}
  Driver(const Driver&) = delete;
  Driver& operator=(const Driver&) = delete;
  virtual ~Driver() = default;

  /// Writes the inputs it feeds, from the simulated time and the outputs of the previous step
  /// (already in `signals`). Leaves every other input untouched.
  virtual void update(double sim_time_s, model::Signals& signals) noexcept = 0;

 protected:
  [[nodiscard]] bool feeds(model::Signal s) const noexcept { return feeds_[model::index(s)]; }
  [[nodiscard]] bool feeds(std::size_t slot) const noexcept { return feeds_[slot]; }

 private:
  io::InputSet feeds_;
};

}  // namespace rig::driver
