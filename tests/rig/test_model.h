#pragma once
/// @file
/// A test-only SteppedModel: a unit mass on a spring and damper, forced by throttle_pedal [N]
/// (semi-implicit Euler). It can charge a fake clock with compute time per step and produce a
/// NaN or a vehicle fault at a chosen step.

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "model/stepped_model.h"

namespace rig::test {

class OscillatorModel final : public model::SteppedModel {
 public:
  explicit OscillatorModel(double h) : h_(h) {}
  [[nodiscard]] double step_size_s() const noexcept override { return h_; }
  [[nodiscard]] double time_s() const noexcept override { return static_cast<double>(steps_) * h_; }
  model::StepStatus step(model::Signals& s) noexcept override {
    if (on_step) on_step(steps_);
    const double u = s[model::Signal::kThrottlePedal];
    if (nan_at_step >= 0 && steps_ == static_cast<std::uint64_t>(nan_at_step)) {
      s.set(model::Signal::kVehicleSpeed, -std::numeric_limits<double>::infinity());
      return model::StepStatus::kNonFinite;  // with a non-finite output, as a model would
    }
    if (fault_at_step >= 0 && steps_ >= static_cast<std::uint64_t>(fault_at_step)) {
      fault_ = {model::FaultKind::kRoll, 1, -1, time_s() + h_, 1.25, 1.0};
      return model::StepStatus::kVehicleFault;  // the state stays (x, v at the last good step)
    }
    v_ += h_ * (u - k_ * x_ - c_ * v_);
    x_ += h_ * v_;
    ++steps_;
    s.set(model::Signal::kPositionX, x_);
    s.set(model::Signal::kVehicleSpeed, v_);
    return model::StepStatus::kOk;
  }
  [[nodiscard]] model::ModelFault last_fault() const noexcept override { return fault_; }
  void fill_report(model::ModelReport& r) const noexcept override {
    r.time_s = time_s();
    r.unit_count = 1;
    r.units[0].position_m[0] = x_;
  }
  std::function<void(std::uint64_t)> on_step;  ///< called at each step (fake compute time)
  std::int64_t nan_at_step = -1;
  std::int64_t fault_at_step = -1;  ///< from this step on: a roll fault of unit 1 (1.25 > 1 rad)
  [[nodiscard]] std::uint64_t steps() const noexcept { return steps_; }

 private:
  double h_;
  double k_ = 4.0, c_ = 0.4, x_ = 0.0, v_ = 0.0;
  std::uint64_t steps_ = 0;
  model::ModelFault fault_{};
};

}  // namespace rig::test
