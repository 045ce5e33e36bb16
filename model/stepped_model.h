#pragma once
/// @file
/// The interface through which the executive steps any model (quarter car, vehicle, combination).

#include "model/report.h"
#include "model/signals.h"

namespace rig::model {

/// Result of one step. The RT path uses codes, never exceptions.
enum class StepStatus { kOk, kNonFinite };

/// A model advanced by fixed steps of the modified implicit Euler method. Implementations
/// allocate only at construction; step() and fill_report() never allocate, block or throw.
class SteppedModel {
 public:
  SteppedModel() = default;
  SteppedModel(const SteppedModel&) = delete;
  SteppedModel& operator=(const SteppedModel&) = delete;
  virtual ~SteppedModel() = default;

  /// Integration step size h [s].
  [[nodiscard]] virtual double step_size_s() const noexcept = 0;
  /// Simulated time [s].
  [[nodiscard]] virtual double time_s() const noexcept = 0;
  /// Advances by one step h: reads the input signals, writes the output signals.
  /// Returns kNonFinite (and leaves the state at its last finite value) if the step produced a
  /// NaN or infinity.
  virtual StepStatus step(Signals& signals) noexcept = 0;
  /// Writes the current state for tools.
  virtual void fill_report(ModelReport& report) const noexcept = 0;
};

}  // namespace rig::model
