#include "model/vehicle/vehicle_model.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "model/vehicle/drivetrain.h"
#include "model/vehicle/gear_selection.h"
#include "model/vehicle/road_start.h"
#include "model/vehicle/vehicle_signals.h"

namespace rig::model::vehicle {

VehicleModel::VehicleModel(const VehicleParams& params, double step_size_s, int unit_index)
    : p_(params), h_(step_size_s), unit_(unit_index), fault_check_(p_) {
  if (p_.axles.empty() || 2 * p_.axles.size() > static_cast<std::size_t>(kMaxWheels)) {
    throw std::invalid_argument("vehicle: need 1.." + std::to_string(kMaxWheels / 2) + " axles");
  }
  if (!(h_ > 0)) throw std::invalid_argument("vehicle: step size must be > 0");
  if (unit_ < 0 || unit_ >= kMaxUnits) {
    throw std::invalid_argument("vehicle: unit index " + std::to_string(unit_) + " not in 0.." +
                                std::to_string(kMaxUnits - 1));
  }
  work_.wheel_count = 2 * static_cast<int>(p_.axles.size());
  state_ = make_state(p_, driven_wheels(p_).count);
  saved_ = state_;
  blocks_ = std::make_unique<VehicleBlocks>(p_, state_, inputs_, work_);
  zero_rate_ = Eigen::VectorXd::Zero(coordinate_size());
  reset(0, 0, 0);
}

VehicleModel::~VehicleModel() = default;

void VehicleModel::reset(double x_m, double y_m, double yaw_rad) noexcept {
  place_at_rest(state_, p_, x_m, y_m, yaw_rad);
  blocks_->place_leaf_axles_at_rest();
  place_on_road(state_, p_, blocks_->framework());  // a surface: its height and slope there
  place_free_bodies(p_, state_);
  work_.wheels.fill(WheelWork{});
  blocks_->update_contacts(0.0);
  blocks_->update_outputs();
}

void VehicleModel::set_forward_speed(double speed_mps) noexcept {
  const Vec6 old_y = state_.framework_y.head<6>(), old_z = state_.framework_z.head<6>();
  state_.framework_z(0) = speed_mps;
  carry_free_bodies(p_, old_y, old_z, state_);
  double carrier = 0;
  for (int i = 0; i < work_.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    state_.spin_radps[k] = speed_mps / work_.wheels[k].tire.kinematics.rolling_radius_m;
    carrier += state_.spin_radps[k];
  }
  state_.drivetrain_z(1) = carrier / work_.wheel_count;
  work_.carrier_speed_radps = state_.drivetrain_z(1);
  // the automatic's gear for this speed and the engine turning with the locked-up converter
  const DrivetrainParams& d = p_.drivetrain;
  state_.gear = gear_for_speed(d, work_.carrier_speed_radps);
  state_.last_shift_s = state_.time_s;
  state_.shift_from_gear = 0;
  const double turbine = ratio_of(d, state_.gear) * work_.carrier_speed_radps;
  state_.drivetrain_z(0) = std::max(d.idle_speed_radps, turbine);
}

double VehicleModel::wheel_load_n(int i) const noexcept {
  return work_.wheels[static_cast<std::size_t>(i)].out.load_n;
}

StepStatus VehicleModel::step(Signals& signals) noexcept {
  set_inputs(signals);
  begin_step(h_);
  finish_step(h_, zero_rate_);  // no constraint forces
  if (last_status_ != StepStatus::kOk) return last_status_;
  write_outputs(signals);
  return StepStatus::kOk;
}

void VehicleModel::set_inputs(const Signals& signals) noexcept {
  inputs_ = read_inputs(p_, unit_, signals);
}

void VehicleModel::begin_step(double h) noexcept {
  saved_ = state_;
  blocks_->steering_system().begin_step(h);  // the overriding gear follows its command
  // the drive train's step: ratios, lock-up and torque cut from the start state, frozen
  const Engagement e = select_gear(p_.drivetrain, inputs_, state_.drivetrain_z(1), state_);
  work_.turbine_ratio = e.turbine_ratio;
  work_.output_ratio = e.output_ratio;
  work_.engine_torque_cut_nm = e.engine_torque_cut_nm;
  const double target = lockup_fraction(p_.drivetrain, e.turbine_ratio * state_.drivetrain_z(1),
                                        state_.drivetrain_z(0));
  const double ramp =
      p_.drivetrain.lockup_engage_time_s > 0 ? h / p_.drivetrain.lockup_engage_time_s : 1.0;
  if (state_.shift_from_gear == 0)  // a running shift holds it as it is
    state_.lockup_fraction =
        std::min(target, state_.lockup_fraction + ramp);  // closes slowly, opens at once
  work_.lockup_fraction = state_.lockup_fraction;
  blocks_->update_contacts(h);
  blocks_->sequence().begin_step(h);  // eq. (8) up to z^u = M_VI^-1 q of the framework (eq. 46)
}

void VehicleModel::finish_step(double h, ConstVectorRef extra_rate) noexcept {
  blocks_->sequence().finish_step(h, extra_rate);          // eq. (45)
  fault_ = fault_check_.check(state_, saved_.time_s + h);  // before any output
  if (fault_.kind != FaultKind::kNone) {
    state_ = saved_;  // the last fault-free state
    last_status_ = step_status(fault_.kind);
    return;
  }
  last_status_ = StepStatus::kOk;
  state_.time_s += h;
  const auto& z = state_.framework_z;
  const Vec3 w = z.segment<3>(3);
  state_.acceleration_mps2 =
      (z.segment<3>(0) - saved_.framework_z.segment<3>(0)) / h + w.cross(z.segment<3>(0));
  blocks_->update_outputs();
  for (int i = 0; i < work_.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    state_.lateral_force_n[k] = work_.wheels[k].out.force_y_n;
    state_.long_force_n[k] = work_.wheels[k].out.force_x_n;
    state_.shaft_torque_nm[k] = work_.wheels[k].shaft_torque_nm;
  }
}

void VehicleModel::revert_step() noexcept {
  if (last_status_ != StepStatus::kOk) return;  // a failed step was already undone
  state_ = saved_;
  blocks_->update_outputs();
  last_status_ = StepStatus::kNonFinite;
}

void VehicleModel::write_outputs(Signals& s) const noexcept {
  vehicle::write_outputs(state_, inputs_, work_, s);
}

void VehicleModel::fill_report(ModelReport& report) const noexcept {
  vehicle::fill_report(state_, inputs_, work_, report);
  fill_free_body_report(p_, state_, report);
  const VehicleFramework& f = blocks_->framework();
  if (f.twist_index() >= 0) {  // frame torsion (frame/frame_torsion.h)
    UnitReport& u = report.units[0];
    u.frame_twist_rad = state_.framework_y(f.twist_index());
    u.frame_twist_rate_radps = state_.framework_z(f.twist_index());
    u.frame_torsion_moment_nm = f.torsion_moment_nm(state_.framework_y, state_.framework_z);
  }
  mark_slip_validity(p_.slip_mask_speed_mps, report.units[0]);
}

// ---- CouplableSystem: the sequential stepper's framework view ----
Eigen::Index VehicleModel::coordinate_size() const noexcept {
  return blocks_->sequence().coordinate_size();
}
solver::CouplableSystem::ConstVectorRef VehicleModel::coordinates() const noexcept {
  return blocks_->sequence().coordinates();
}
solver::CouplableSystem::ConstVectorRef VehicleModel::speeds() const noexcept {
  return blocks_->sequence().speeds();
}
solver::CouplableSystem::ConstMatrixRef VehicleModel::kinematics_inverse() const noexcept {
  return blocks_->sequence().kinematics_inverse();
}
solver::CouplableSystem::ConstVectorRef VehicleModel::unconstrained_rate() const noexcept {
  return blocks_->sequence().unconstrained_rate();
}
void VehicleModel::solve_mass(ConstMatrixRef b, MatrixRef x) const noexcept {
  blocks_->sequence().solve_mass(b, x);
}
void VehicleModel::solve_mass_leading(ConstMatrixRef b, MatrixRef x) const noexcept {
  blocks_->sequence().solve_mass_leading(b, x);
}
const Eigen::MatrixXd& VehicleModel::modified_mass_matrix() const noexcept {
  return blocks_->framework_stepper().modified_mass_matrix();
}
const Eigen::VectorXd& VehicleModel::applied_forces() const noexcept {
  return blocks_->framework_stepper().applied_forces();
}

}  // namespace rig::model::vehicle
