#pragma once
/// @file
/// The driver phase of a cycle: fills the inputs that no ECU provides.

#include "model/signals.h"

namespace rig::driver {

/// A source of driver inputs: an open-loop maneuver table, a closed-loop driver, ... Runs on the
/// RT thread after the inputs phase: no allocation, no blocking, no exceptions.
class Driver {
 public:
  Driver() = default;
  Driver(const Driver&) = delete;
  Driver& operator=(const Driver&) = delete;
  virtual ~Driver() = default;

  /// Writes every input whose source is SignalSource::kDriver, from the simulated time and the
  /// outputs of the previous step (already in `signals`). Leaves kCan inputs untouched.
  virtual void update(double sim_time_s, model::Signals& signals) noexcept = 0;
};

}  // namespace rig::driver
