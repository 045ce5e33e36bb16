#pragma once
/// @file
/// The quarter car as a SteppedModel for the executive: one unit with one wheel.
/// Inputs: throttle_pedal (x max_drive_torque_nm) and brake_pressure_front_pa (x brake gain).
/// Outputs: vehicle_speed_mps, wheel_speed_fl_radps, longitudinal_accel_mps2, position_x_m.

#include <memory>

#include "model/paper/quarter_car_params.h"
#include "model/stepped_model.h"

namespace rig::model::paper {

class QuarterCar;

class QuarterCarModel final : public rig::model::SteppedModel {
 public:
  /// Allocates here only.
  QuarterCarModel(const QuarterCarParams& params, double step_size_s);
  ~QuarterCarModel() override;

  [[nodiscard]] double step_size_s() const noexcept override { return step_size_s_; }
  [[nodiscard]] double time_s() const noexcept override;
  StepStatus step(Signals& signals) noexcept override;
  void fill_report(ModelReport& report) const noexcept override;

  /// The simulation underneath (for tools and tests).
  [[nodiscard]] const QuarterCar& quarter_car() const noexcept { return *car_; }
  [[nodiscard]] QuarterCar& quarter_car() noexcept { return *car_; }

 private:
  QuarterCarParams params_;
  double step_size_s_;
  std::unique_ptr<QuarterCar> car_;
};

}  // namespace rig::model::paper
