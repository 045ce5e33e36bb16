#include "model/paper/quarter_car_model.h"

#include <algorithm>
#include <cmath>

#include "model/paper/quarter_car.h"

namespace rig::model::paper {

QuarterCarModel::QuarterCarModel(const QuarterCarParams& params, double step_size_s)
    : params_(params), step_size_s_(step_size_s), car_(std::make_unique<QuarterCar>(params)) {}

QuarterCarModel::~QuarterCarModel() = default;

double QuarterCarModel::time_s() const noexcept { return car_->time_s(); }

StepStatus QuarterCarModel::step(Signals& signals) noexcept {
  QuarterCarInputs in;
  const double throttle = std::isfinite(signals[Signal::kThrottlePedal])
                              ? std::clamp(signals[Signal::kThrottlePedal], 0.0, 1.0)
                              : 0.0;
  const double pressure = std::isfinite(signals[Signal::kBrakePressureFront])
                              ? std::max(0.0, signals[Signal::kBrakePressureFront])
                              : 0.0;
  in.drive_torque_nm = throttle * params_.max_drive_torque_nm;
  in.brake_torque_limit_nm = pressure * params_.brake_gain_nm_per_pa;
  const QuarterCar::State before = car_->state();
  car_->step(step_size_s_, in);
  const QuarterCar::State after = car_->state();
  if (!std::isfinite(after.speed_mps) || !std::isfinite(after.spin_radps) ||
      !std::isfinite(after.position_m) || !std::isfinite(after.wheel_angle_rad) ||
      !std::isfinite(after.deflection_m)) {
    car_->set_state(before);  // the contract: keep the last finite state
    return StepStatus::kNonFinite;
  }
  signals.set(Signal::kVehicleSpeed, car_->speed_mps());
  signals.set(Signal::kWheelSpeedFL, car_->wheel_speed_radps());
  signals.set(Signal::kLongitudinalAccel, car_->acceleration_mps2());
  signals.set(Signal::kPositionX, car_->position_m());
  return StepStatus::kOk;
}

void QuarterCarModel::fill_report(ModelReport& report) const noexcept {
  report.time_s = car_->time_s();
  report.unit_count = 1;
  UnitReport& unit = report.units[0];
  unit.position_m = {car_->position_m(), 0.0, 0.0};
  unit.orientation_rad = {0.0, -std::atan(params_.grade), 0.0};
  unit.velocity_mps = {car_->speed_mps(), 0.0, 0.0};
  unit.angular_velocity_radps = {0.0, 0.0, 0.0};
  unit.acceleration_mps2 = {car_->acceleration_mps2(), 0.0, 0.0};
  unit.wheel_count = 1;
  WheelReport& wheel = unit.wheels[0];
  wheel.spin_radps = car_->wheel_speed_radps();
  wheel.force_x_n = car_->tire_force_n();
  wheel.load_n = car_->wheel_load_n();
  wheel.deflection_x_m = car_->deflection_m();
  wheel.brake_torque_nm = car_->brake_torque_nm();
  wheel.drive_torque_nm = car_->drive_torque_nm();
  wheel.long_speed_mps = car_->speed_mps();  // the contact point moves with the car (eq. 9)
  wheel.rolling_radius_m = params_.wheel_radius_m;
  wheel.tire_load_n = car_->wheel_load_n();
  report.joint_count = 0;
}

}  // namespace rig::model::paper
