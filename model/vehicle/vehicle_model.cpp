#include "model/vehicle/vehicle_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rig::model::vehicle {

VehicleModel::VehicleModel(const VehicleParams& params, double step_size_s)
    : p_(params), h_(step_size_s) {
  if (p_.axles.empty() || 2 * p_.axles.size() > static_cast<std::size_t>(kMaxWheels)) {
    throw std::invalid_argument("vehicle: need 1.." + std::to_string(kMaxWheels / 2) + " axles");
  }
  if (!(h_ > 0)) throw std::invalid_argument("vehicle: step size must be > 0");
  bus_.wheel_count = 2 * static_cast<int>(p_.axles.size());
  std::array<int, kMaxWheels> driven{};
  int driven_count = 0;
  for (int i = 0; i < bus_.wheel_count; ++i) {
    axle_of_wheel_[static_cast<std::size_t>(i)] = i / 2;
    if (p_.axles[static_cast<std::size_t>(i / 2)].driven)
      driven[static_cast<std::size_t>(driven_count++)] = i;
  }
  kinematics_ = std::make_unique<SuspensionKinematics>(p_);
  framework_ = std::make_unique<VehicleFramework>(bus_, p_);
  if (driven_count > 0)
    shafts_ = std::make_unique<HalfShafts>(bus_, p_.drivetrain, driven, driven_count);
  drivetrain_ = std::make_unique<Drivetrain>(bus_, p_.drivetrain, shafts_.get());
  steering_ = std::make_unique<Steering>(bus_, p_.steering);
  wheel_stage_ = std::make_unique<WheelSpinStage>(bus_, p_, axle_of_wheel_, shafts_.get(),
                                                  *steering_, *drivetrain_);

  solver::ArrowheadPartition partition;
  partition.body_size = 6;
  partition.leaf_sizes.assign(p_.axles.size(), 2);
  framework_stepper_ =
      std::make_unique<solver::MechanicalStepper<Eigen::Dynamic, solver::ArrowheadFactorization>>(
          *framework_, partition);
  engine_ = std::make_unique<solver::Engine>(*framework_stepper_);
  // eq. (8) order: force elements (tires, half shafts), subsystems, framework last
  for (int i = 0; i < bus_.wheel_count; ++i) {
    const auto& axle = p_.axles[static_cast<std::size_t>(i / 2)];
    tires_.push_back(
        std::make_unique<TireDeflection>(bus_, axle.tire, i, axle.tire.velocity_floor_mps));
    tire_steppers_.push_back(std::make_unique<solver::ForceElementStepper<2>>(*tires_.back()));
    engine_->add_stage(*tire_steppers_.back());
  }
  if (shafts_) {
    shaft_stepper_ = std::make_unique<solver::ForceElementStepper<Eigen::Dynamic>>(*shafts_);
    engine_->add_stage(*shaft_stepper_);
  }
  // A unit without driven axles (a trailer) has no use for the drive train, one without
  // steered axles none for the steering: their stages are left out (their states stay at rest).
  const bool any_steered =
      std::any_of(p_.axles.begin(), p_.axles.end(), [](const AxleParams& a) { return a.steered; });
  drivetrain_stepper_ = std::make_unique<solver::MechanicalStepper<2>>(*drivetrain_);
  if (driven_count > 0) engine_->add_stage(*drivetrain_stepper_);
  steering_stepper_ = std::make_unique<solver::MechanicalStepper<2>>(*steering_);
  if (any_steered) engine_->add_stage(*steering_stepper_);
  engine_->add_stage(*wheel_stage_);

  saved_y_ = Eigen::VectorXd::Zero(framework_->size());
  saved_z_ = Eigen::VectorXd::Zero(framework_->size());
  saved_shafts_ = Eigen::VectorXd::Zero(driven_count);
  zero_rate_ = Eigen::VectorXd::Zero(framework_->size());
  reset(0, 0, 0);
}

VehicleModel::~VehicleModel() = default;

void VehicleModel::reset(double x_m, double y_m, double yaw_rad) noexcept {
  auto& y = framework_->coordinates();
  auto& z = framework_->speeds();
  y.setZero();
  z.setZero();
  y(0) = x_m;
  y(1) = y_m;
  y(2) = p_.chassis.cg_height_m;
  y(3) = yaw_rad;
  for (auto& t : tires_) t->state().setZero();
  bus_.deflection_m.fill(0);
  if (shafts_) shafts_->state().setZero();
  drivetrain_->coordinates().setZero();
  drivetrain_->speeds() << p_.drivetrain.idle_speed_radps, 0;
  steering_->coordinates().setZero();
  steering_->speeds().setZero();
  for (int i = 0; i < bus_.wheel_count; ++i) {
    auto& w = bus_.wheels[static_cast<std::size_t>(i)];
    w = WheelBus{};
  }
  time_s_ = 0;
  last_shift_s_ = -1e9;
  bus_.gear = 0;
  update_contacts();
  for (int i = 0; i < bus_.wheel_count; ++i) {
    wheel_out_[static_cast<std::size_t>(i)] = framework_->wheel_forces(y, z, i);
  }
}

void VehicleModel::set_forward_speed(double speed_mps) noexcept {
  framework_->speeds()(0) = speed_mps;
  double carrier = 0;
  for (int i = 0; i < bus_.wheel_count; ++i) {
    auto& w = bus_.wheels[static_cast<std::size_t>(i)];
    w.spin_radps = speed_mps / w.radius_dynamic_m;
    carrier += w.spin_radps;
  }
  drivetrain_->speeds()(1) = carrier / bus_.wheel_count;
  bus_.carrier_speed_radps = drivetrain_->speeds()(1);
  // the automatic's gear for this speed (lowest gear below the part-load upshift point) and
  // the engine turning with the locked-up converter
  const auto& d = p_.drivetrain;
  const int top = static_cast<int>(d.gear_ratios.size());
  int gear = 1;
  while (gear < top && d.gear_ratios[static_cast<std::size_t>(gear - 1)] * d.final_drive_ratio *
                               std::abs(bus_.carrier_speed_radps) >
                           d.upshift_speed_low_radps) {
    ++gear;
  }
  bus_.gear = gear;
  last_shift_s_ = time_s_;
  const double turbine = d.gear_ratios[static_cast<std::size_t>(gear - 1)] * d.final_drive_ratio *
                         bus_.carrier_speed_radps;
  drivetrain_->speeds()(0) = std::max(d.idle_speed_radps, turbine);
}

double VehicleModel::wheel_load_n(int i) const noexcept {
  return wheel_out_[static_cast<std::size_t>(i)].load_n;
}

void VehicleModel::read_inputs(const Signals& s) noexcept {
  const auto in = [&](Signal id, double fallback) {
    const double v = s[id];
    return s.valid[index(id)] && std::isfinite(v) ? v : fallback;
  };
  bus_.throttle = std::clamp(in(Signal::kThrottlePedal, 0.0), 0.0, 1.0);
  const double front = std::max(0.0, in(Signal::kBrakePressureFront, 0.0));
  const double rear = std::max(0.0, in(Signal::kBrakePressureRear, 0.0));
  for (int i = 0; i < bus_.wheel_count; ++i) {
    auto& w = bus_.wheels[static_cast<std::size_t>(i)];
    const auto& a = p_.axles[static_cast<std::size_t>(i / 2)];
    w.brake_pressure_pa = a.brake_circuit == 0 ? front : rear;
    w.brake_capacity_nm = a.brake_gain_nm_per_pa * w.brake_pressure_pa;
  }
  bus_.steering_angle_cmd_rad = in(Signal::kSteeringWheelAngleCmd, 0.0);
  bus_.hand_torque_cmd_nm = in(Signal::kSteeringWheelTorqueCmd, 0.0);
  // the assist input while valid when routed to it (SteeringParams::assist_from_input)
  bus_.assist_from_input = p_.steering.assist_from_input && s.valid[index(Signal::kAssistTorque)];
  bus_.assist_input_nm = in(Signal::kAssistTorque, 0.0);
  gear_request_ = static_cast<int>(std::lround(in(Signal::kGearRequest, 99.0)));
}

void VehicleModel::select_gear() noexcept {
  const auto& d = p_.drivetrain;
  const int top = static_cast<int>(d.gear_ratios.size());
  int gear = bus_.gear;
  if (gear_request_ != 99) {
    gear = std::clamp(gear_request_, -1, top);
  } else {
    if (gear < 1) gear = 1;
    // shift schedule on the turbine speed, throttle-dependent upshift point, with a dwell time
    const double turbine = d.gear_ratios[static_cast<std::size_t>(gear - 1)] * d.final_drive_ratio *
                           drivetrain_->carrier_speed_radps();
    const double up = d.upshift_speed_low_radps +
                      bus_.throttle * (d.upshift_speed_high_radps - d.upshift_speed_low_radps);
    if (time_s_ - last_shift_s_ >= d.shift_dwell_s) {
      if (turbine > up && gear < top)
        ++gear;
      else if (gear > 1) {
        const double lower = d.gear_ratios[static_cast<std::size_t>(gear - 2)] *
                             d.final_drive_ratio * drivetrain_->carrier_speed_radps();
        if (lower < d.downshift_speed_radps * 2.0 && turbine < d.downshift_speed_radps) --gear;
      }
    }
  }
  if (gear != bus_.gear) last_shift_s_ = time_s_;
  bus_.gear = gear;
  if (gear > 0)
    bus_.total_ratio = d.gear_ratios[static_cast<std::size_t>(gear - 1)] * d.final_drive_ratio;
  else if (gear < 0)
    bus_.total_ratio = -d.reverse_ratio * d.final_drive_ratio;
  else
    bus_.total_ratio = 0;
}

void VehicleModel::update_contacts() noexcept {
  const auto& y = framework_->coordinates();
  const auto& z = framework_->speeds();
  kinematics_->update(y, bus_);  // eq. (29) at y_V(k), before any contact is evaluated
  const Mat3 rot = body_to_road(y(3), y(4), y(5));
  for (int i = 0; i < bus_.wheel_count; ++i) {
    auto& w = bus_.wheels[static_cast<std::size_t>(i)];
    const TireParams& t = p_.axles[static_cast<std::size_t>(i / 2)].tire;
    const WheelContact c = framework_->contact(rot, y, z, i);
    w.vx_mps = c.vx_mps;
    w.vy_mps = c.vy_mps;
    w.load_n = vertical_tire_force_n(c.penetration_m, c.penetration_rate_mps,
                                     t.vertical_stiffness_npm, t.vertical_damping_nspm);
    w.radius_dynamic_m = dynamic_radius_m(t.radius_unloaded_m, c.penetration_m);
    const double mu =
        (i % 2 == 1 && p_.road.friction_right >= 0) ? p_.road.friction_right : p_.road.friction;
    w.curves = tmeasy_curves(t, w.load_n, mu);
    w.f_per_slip = tmeasy_slip(w.curves, w.vx_mps, w.vy_mps, w.spin_radps, w.radius_dynamic_m,
                               t.velocity_floor_mps)
                       .f_per_slip;
  }
  bus_.carrier_speed_radps = drivetrain_->carrier_speed_radps();
}

void VehicleModel::save_state() noexcept {
  saved_y_ = framework_->coordinates();
  saved_z_ = framework_->speeds();
  if (shafts_) saved_shafts_ = shafts_->state();
  saved_dt_y_ = drivetrain_->coordinates();
  saved_dt_z_ = drivetrain_->speeds();
  saved_st_y_ = steering_->coordinates();
  saved_st_z_ = steering_->speeds();
  for (int i = 0; i < bus_.wheel_count; ++i)
    saved_spin_[static_cast<std::size_t>(i)] = bus_.wheels[static_cast<std::size_t>(i)].spin_radps;
  saved_deflection_ = bus_.deflection_m;
}

void VehicleModel::restore_state() noexcept {
  framework_->coordinates() = saved_y_;
  framework_->speeds() = saved_z_;
  if (shafts_) shafts_->state() = saved_shafts_;
  drivetrain_->coordinates() = saved_dt_y_;
  drivetrain_->speeds() = saved_dt_z_;
  steering_->coordinates() = saved_st_y_;
  steering_->speeds() = saved_st_z_;
  for (int i = 0; i < bus_.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    bus_.wheels[k].spin_radps = saved_spin_[k];
    tires_[k]->state() << saved_deflection_[2 * k], saved_deflection_[2 * k + 1];
  }
  bus_.deflection_m = saved_deflection_;
}

bool VehicleModel::state_finite() const noexcept {
  bool ok = framework_->coordinates().allFinite() && framework_->speeds().allFinite() &&
            drivetrain_->speeds().allFinite() && steering_->coordinates().allFinite() &&
            steering_->speeds().allFinite();
  for (int i = 0; i < bus_.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    ok = ok && std::isfinite(bus_.wheels[k].spin_radps) &&
         std::isfinite(bus_.deflection_m[2 * k]) && std::isfinite(bus_.deflection_m[2 * k + 1]);
  }
  return ok;
}

StepStatus VehicleModel::step(Signals& signals) noexcept {
  set_inputs(signals);
  begin_step(h_);
  finish_step(h_, zero_rate_);  // no constraint forces: exactly Engine::step
  if (last_status_ != StepStatus::kOk) return last_status_;
  write_outputs(signals);
  return StepStatus::kOk;
}

void VehicleModel::set_inputs(const Signals& signals) noexcept { read_inputs(signals); }

Eigen::Index VehicleModel::coordinate_size() const noexcept { return engine_->coordinate_size(); }

void VehicleModel::begin_step(double h) noexcept {
  select_gear();
  update_contacts();
  save_state();
  saved_accel_body_ = accel_body_;
  engine_->begin_step(h);  // eq. (8) up to z^u = M_VI^-1 q of the framework (eq. 46)
}

solver::CouplableSystem::ConstVectorRef VehicleModel::coordinates() const noexcept {
  return engine_->coordinates();
}
solver::CouplableSystem::ConstVectorRef VehicleModel::speeds() const noexcept {
  return engine_->speeds();
}
solver::CouplableSystem::ConstMatrixRef VehicleModel::kinematics_inverse() const noexcept {
  return engine_->kinematics_inverse();
}
solver::CouplableSystem::ConstVectorRef VehicleModel::unconstrained_rate() const noexcept {
  return engine_->unconstrained_rate();
}
void VehicleModel::solve_mass(ConstMatrixRef b, MatrixRef x) const noexcept {
  engine_->solve_mass(b, x);
}
void VehicleModel::solve_mass_leading(ConstMatrixRef b, MatrixRef x) const noexcept {
  engine_->solve_mass_leading(b, x);
}

void VehicleModel::finish_step(double h, ConstVectorRef extra_rate) noexcept {
  engine_->finish_step(h, extra_rate);  // eq. (45)
  if (!state_finite()) {
    restore_state();
    last_status_ = StepStatus::kNonFinite;
    return;
  }
  last_status_ = StepStatus::kOk;
  time_s_ += h;
  const auto& y = framework_->coordinates();
  const auto& z = framework_->speeds();
  const Vec3 w = z.segment<3>(3);
  accel_body_ = (z.segment<3>(0) - saved_z_.segment<3>(0)) / h + w.cross(z.segment<3>(0));
  const Mat3 rot = body_to_road(y(3), y(4), y(5));
  for (int i = 0; i < bus_.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    wheel_out_[k] = framework_->wheel_forces(rot, y, z, i);
    bus_.wheels[k].force_x_n = wheel_out_[k].force_x_n;
    bus_.wheels[k].force_y_n = wheel_out_[k].force_y_n;
    bus_.wheels[k].slip_x = wheel_out_[k].slip_x;
    bus_.wheels[k].slip_y = wheel_out_[k].slip_y;
  }
  const double tb = steering_->torsion_bar_torque_nm(steering_->coordinates(), steering_->speeds());
  bus_.torsion_bar_torque_nm = tb;
  bus_.assist_torque_nm = steering_->assist_torque_nm(tb);
  bus_.engine_torque_nm =
      engine_torque_nm(p_.drivetrain, bus_.throttle, drivetrain_->engine_speed_radps());
}

const Eigen::MatrixXd& VehicleModel::modified_mass_matrix() const noexcept {
  return framework_stepper_->modified_mass_matrix();
}
const Eigen::VectorXd& VehicleModel::applied_forces() const noexcept {
  return framework_stepper_->applied_forces();
}

void VehicleModel::revert_step() noexcept {
  if (last_status_ != StepStatus::kOk) return;  // a failed step was already undone
  restore_state();
  time_s_ -= h_;
  accel_body_ = saved_accel_body_;
  const auto& y = framework_->coordinates();
  const auto& z = framework_->speeds();
  for (int i = 0; i < bus_.wheel_count; ++i) {
    wheel_out_[static_cast<std::size_t>(i)] = framework_->wheel_forces(y, z, i);
  }
  last_status_ = StepStatus::kNonFinite;
}

void VehicleModel::write_outputs(Signals& s) noexcept {
  const auto& y = framework_->coordinates();
  const auto& z = framework_->speeds();
  const int n = bus_.wheel_count;
  const auto wheel = [&](int i) -> const WheelBus& {
    return bus_.wheels[static_cast<std::size_t>(i)];
  };
  s.set(Signal::kVehicleSpeed, z(0));
  s.set(Signal::kWheelSpeedFL, wheel(0).spin_radps);
  s.set(Signal::kWheelSpeedFR, wheel(1).spin_radps);
  s.set(Signal::kWheelSpeedRL, wheel(n - 2).spin_radps);
  s.set(Signal::kWheelSpeedRR, wheel(n - 1).spin_radps);
  s.set(Signal::kLongitudinalAccel, accel_body_.x());
  s.set(Signal::kLateralAccel, accel_body_.y());
  s.set(Signal::kYawRate, z(5));
  s.set(Signal::kSteeringWheelAngle, steering_->coordinates()(0));
  s.set(Signal::kSteeringWheelSpeed, steering_->speeds()(0));
  s.set(Signal::kTorsionBarTorque, bus_.torsion_bar_torque_nm);
  s.set(Signal::kRackPosition, steering_->coordinates()(1));
  s.set(Signal::kRackForce, bus_.rack_force_n);
  s.set(Signal::kEngineSpeed, drivetrain_->engine_speed_radps());
  s.set(Signal::kGear, bus_.gear);
  s.set(Signal::kBrakePressureFL, wheel(0).brake_pressure_pa);
  s.set(Signal::kBrakePressureFR, wheel(1).brake_pressure_pa);
  s.set(Signal::kBrakePressureRL, wheel(n - 2).brake_pressure_pa);
  s.set(Signal::kBrakePressureRR, wheel(n - 1).brake_pressure_pa);
  s.set(Signal::kPositionX, y(0));
  s.set(Signal::kPositionY, y(1));
  s.set(Signal::kHeading, y(3));
}

void VehicleModel::fill_report(ModelReport& report) const noexcept {
  const auto& y = framework_->coordinates();
  const auto& z = framework_->speeds();
  report.time_s = time_s_;
  report.unit_count = 1;
  UnitReport& u = report.units[0];
  for (int k = 0; k < 3; ++k) {
    u.position_m[static_cast<std::size_t>(k)] = y(k);
    u.velocity_mps[static_cast<std::size_t>(k)] = z(k);
    u.angular_velocity_radps[static_cast<std::size_t>(k)] = z(3 + k);
    u.acceleration_mps2[static_cast<std::size_t>(k)] = accel_body_(k);
  }
  u.orientation_rad = {y(5), y(4), y(3)};
  u.wheel_count = bus_.wheel_count;
  for (int i = 0; i < bus_.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const WheelBus& w = bus_.wheels[k];
    WheelReport& r = u.wheels[k];
    r.spin_radps = w.spin_radps;
    r.slip_x = w.slip_x;
    r.slip_y = w.slip_y;
    r.force_x_n = w.force_x_n;
    r.force_y_n = w.force_y_n;
    r.load_n = wheel_out_[k].load_n;
    r.deflection_x_m = bus_.deflection_m[2 * k];
    r.deflection_y_m = bus_.deflection_m[2 * k + 1];
    r.hub_travel_m = y(6 + i);
    r.steer_angle_rad = w.steer_rad;
    r.brake_torque_nm = w.brake_torque_nm;
    r.drive_torque_nm = w.shaft_torque_nm;
  }
  report.steering.wheel_angle_rad = steering_->coordinates()(0);
  report.steering.wheel_torque_nm = bus_.hand_torque_cmd_nm;
  report.steering.torsion_bar_torque_nm = bus_.torsion_bar_torque_nm;
  report.steering.rack_travel_m = steering_->coordinates()(1);
  report.steering.rack_force_n = bus_.rack_force_n;
  report.steering.assist_torque_nm = bus_.assist_torque_nm;
  report.drivetrain.engine_speed_radps = drivetrain_->engine_speed_radps();
  report.drivetrain.engine_torque_nm = bus_.engine_torque_nm;
  report.drivetrain.gear = bus_.gear;
  const int n = bus_.wheel_count;
  report.brake_pressure_pa = {bus_.wheels[0].brake_pressure_pa, bus_.wheels[1].brake_pressure_pa,
                              bus_.wheels[static_cast<std::size_t>(n - 2)].brake_pressure_pa,
                              bus_.wheels[static_cast<std::size_t>(n - 1)].brake_pressure_pa};
  report.joint_count = 0;
}

}  // namespace rig::model::vehicle
