#pragma once
/// @file
/// The column steering system (sec. 2.2): steering wheel + column inertia, torsion bar (its
/// torque is what the assist senses), steering box ratio i_SB (rack travel per pinion angle),
/// rack mass, dry friction in the rack and the column (stick-predicted by the stepper: each sticks
/// or slides at its capacity, SteeringSystem::dry_friction), assist
/// torque on the pinion (input signal or built-in boost curve). The wheel is driven by hand
/// torque or, in angle mode, by a stiff position servo (a steering robot). The optional
/// overriding gear (active front steering): a superposition gear adds its motor's angle / i_ov
/// at the pinion (the torsion bar's lower end at u / i_SB - overlay), so with the hand wheel
/// held the rack moves by overlay x i_SB; the command is the overlay at the pinion, the motor
/// follows it as a first-order lag (overlay_bandwidth_hz) at most at overlay_rate_max_radps.
/// With the boost curve, the EPS's active return (SteeringParams::active_return) brings a
/// released wheel back at low speed. Ignition off: no assist (neither the input nor the boost
/// curve, nor the return).

#include "model/vehicle/steering/steering_system.h"
#include "model/vehicle/vehicle_inputs.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::model::vehicle {

class ColumnSteering final : public SteeringSystem {
 public:
  /// Reads the overlay from state (state.overlay_rad, overlay_rate_radps) and the driver's and
  /// assist inputs.
  ColumnSteering(const SteeringParams& p, VehicleState& state, const VehicleInputs& inputs);
  void begin_step(double h) noexcept override;
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  void force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;
  [[nodiscard]] double torsion_bar_torque_nm(const Vector& y,
                                             const Vector& z) const noexcept override;
  [[nodiscard]] double assist_torque_nm(const Vector& y, const Vector& z) const noexcept override;
  /// rack_friction_n on the rack travel, column_friction_nm on the wheel angle.
  [[nodiscard]] SteeringFriction dry_friction(const Vector& y,
                                              const Vector& z) const noexcept override;
  /// Assist torque for a torsion bar torque (input signal or boost curve; 0 with the ignition
  /// off) [N m].
  [[nodiscard]] double assist_for_torsion_bar_nm(double torsion_bar_nm) const noexcept;
  /// The built-in EPS's active return torque at the pinion (SteeringParams::active_return;
  /// 0 when off, with the ECU's assist or the ignition off) [N m].
  [[nodiscard]] double active_return_nm(const Vector& y, const Vector& z,
                                        double torsion_bar_nm) const noexcept;

 private:
  /// The active return's speed schedule f(v), 0 when it does not act at all.
  [[nodiscard]] double active_return_speed_weight() const noexcept;
  /// -(T_max clamp(theta / theta_sat) + d theta'): the return before its weights [N m].
  [[nodiscard]] double active_return_demand_nm(const Vector& y, const Vector& z) const noexcept;

  const SteeringParams& p_;
  VehicleState& state_;
  const VehicleInputs& inputs_;
};

}  // namespace rig::model::vehicle
