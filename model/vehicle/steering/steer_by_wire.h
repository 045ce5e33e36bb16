#pragma once
/// @file
/// Steer-by-wire (issue 15): no column between the two coordinates. The hand wheel (inertia
/// wheel_inertia_kgm2, damping column_damping_nmspr) takes the driver's torque (or the steering
/// robot in angle mode) and the hand-wheel actuator's feedback torque from the ECU, limited to
/// feedback_torque_max_nm. The rack (rack_mass_kg + the road-wheel motor's inertia reflected
/// through its gear, J / r^2) takes the road-wheel actuator's force: a force command through a
/// first-order lag (VehicleState::rack_actuator_force_n), or a position command through the
/// actuator's own I-PD servo (P and D implicit, the integral explicit in begin_step; designed
/// as a 3rd-order Butterworth lag at rack_actuator_bandwidth_hz, with the measured tie-rod
/// force as load feedforward), both limited to
/// rack_actuator_force_max_n; no valid command: no force (the lag decays to 0). Friction-free.
/// Report: the torsion bar's torque is the hand-wheel's torque sensor (the driver's or robot's
/// torque on the rim); the assist is the rack motor's force at the pinion equivalent, F i_SB.

#include "model/vehicle/steering/steering_system.h"
#include "model/vehicle/vehicle_inputs.h"
#include "model/vehicle/vehicle_params.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle {

class SteerByWire final : public SteeringSystem {
 public:
  /// work: the tie rods' force of the last step (rack_force_n), the position servo's feedforward.
  SteerByWire(const SteeringParams& p, VehicleState& state, const VehicleInputs& inputs,
              const VehicleWorkspace& work);
  void begin_step(double h) noexcept override;
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  void force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;
  [[nodiscard]] double torsion_bar_torque_nm(const Vector& y,
                                             const Vector& z) const noexcept override;
  [[nodiscard]] double assist_torque_nm(const Vector& y, const Vector& z) const noexcept override;
  /// The rack's mass with the road-wheel motor reflected, m_rack + J / r^2 [kg].
  [[nodiscard]] double rack_mass_kg() const noexcept { return rack_mass_kg_; }
  /// The road-wheel actuator's force on the rack at a state [N].
  [[nodiscard]] double rack_actuator_force_n(const Vector& y, const Vector& z) const noexcept;

 private:
  [[nodiscard]] double hand_torque_nm(const Vector& y, const Vector& z) const noexcept;
  [[nodiscard]] double servo_force_n(const Vector& y, const Vector& z) const noexcept;

  const SteeringParams& p_;
  VehicleState& state_;
  const VehicleInputs& inputs_;
  const VehicleWorkspace& work_;
  double rack_mass_kg_;
  double servo_w_radps_;        ///< w = 2 pi f_bw
  double servo_stiffness_npm_;  ///< k_p = 2 m w^2
  double servo_damping_nspm_;   ///< k_d = 2 m w
};

}  // namespace rig::model::vehicle
