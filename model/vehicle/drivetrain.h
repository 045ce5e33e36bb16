#pragma once
/// @file
/// Engine and transmission as a subsystem (eq. 2): speeds [w_e, w_c] = engine and differential
/// input (wheel units). Engine torque map over throttle and speed with idle control; torque
/// converter with lock-up clutch; gear ratio x final drive; the half shafts' common torque
/// loads the differential input (half_shafts.h). Stiff parts (converter, lock-up, shaft
/// damping) enter M_VI through the stepper's finite differences of this 2-DOF block.

#include "model/solver/mechanical_block.h"
#include "model/vehicle/driven_shafts.h"
#include "model/vehicle/vehicle_inputs.h"
#include "model/vehicle/vehicle_params.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle {

/// The engine's drag (friction and pumping) at a speed [N m], >= 0 turning forward.
double engine_drag_nm(const DrivetrainParams& p, double speed_radps) noexcept;

/// Engine torque [N m] at throttle [0..1] and speed, with idle control and drag.
double engine_torque_nm(const DrivetrainParams& p, double throttle, double speed_radps) noexcept;

/// The engine's torque after the gearbox's reduction cut_nm (<= 0): down to the closed-throttle
/// torque at most (a fuel cut). Not running (ignition off): only its drag, no idle control.
double delivered_engine_torque_nm(const DrivetrainParams& p, double throttle, double speed_radps,
                                  double cut_nm, bool running) noexcept;

/// Lock-up clutch engagement [0..1] at a turbine speed (above lockup_start_radps) and near the
/// converter's coupling point (turbine/engine speed ratio). Evaluated once per step from the step's
/// start state (VehicleModel::begin_step) and frozen: as a function of w_t inside the step its
/// slope times the slip makes dT_c/dw_t > 0 at large slip, an unstable mode (~5e4 1/s at a
/// launch) that the linearised implicit Euler of eq. (8) turns over once h lambda > 1.
double lockup_fraction(const DrivetrainParams& p, double turbine_radps,
                       double engine_radps) noexcept;

class Drivetrain final : public solver::MechanicalBlock<2> {
 public:
  /// Its coordinates and speeds are state.drivetrain_y, drivetrain_z; it reads the throttle and
  /// the step's frozen ratios, lock-up fraction and torque cut (workspace).
  Drivetrain(const DrivetrainParams& p, VehicleState& state, const VehicleInputs& inputs,
             const VehicleWorkspace& work, const DrivenShafts* shafts);
  [[nodiscard]] Eigen::Index size() const noexcept override { return 2; }
  [[nodiscard]] Vector& coordinates() noexcept override { return state_.drivetrain_y; }
  [[nodiscard]] Vector& speeds() noexcept override { return state_.drivetrain_z; }
  [[nodiscard]] double carrier_speed_radps() const noexcept { return state_.drivetrain_z(1); }
  [[nodiscard]] double engine_speed_radps() const noexcept { return state_.drivetrain_z(0); }
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  /// Converter + lock-up torque on the engine [N m].
  [[nodiscard]] double coupling_torque_nm(double engine_radps, double carrier_radps) const noexcept;

 private:
  const DrivetrainParams& p_;
  VehicleState& state_;
  const VehicleInputs& inputs_;
  const VehicleWorkspace& work_;
  const DrivenShafts* shafts_;
  double lockup_capacity_;  ///< [N m] (DrivetrainParams::lockup_capacity_nm or the engine's peak)
};

}  // namespace rig::model::vehicle
