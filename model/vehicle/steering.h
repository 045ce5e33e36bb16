#pragma once
/// @file
/// The enhanced rack-and-pinion steering system (sec. 2.2) as a subsystem (eq. 2):
/// coordinates [steering wheel angle, rack travel u]. Steering wheel + column inertia, torsion
/// bar (its torque is what the assist senses), steering box ratio i_SB (rack travel per pinion
/// angle), rack mass, rack dry friction (regularized, its steep slope in M_VI keeps it stable),
/// assist torque on the pinion (input signal or built-in boost curve), and the tie-rod forces
/// from the wheels (VehicleWorkspace::rack_force_n). The wheel is driven by hand torque or, in
/// angle mode, by a stiff position servo (a steering robot). The optional overriding gear of
/// sec. 2.2 in its simple form: an overlay angle added at the pinion (the torsion bar's lower
/// end at u / i_SB - overlay), so with the hand wheel held the rack moves by overlay x i_SB;
/// the overlay follows its command at most at overlay_rate_max_radps (VehicleState).
/// Ignition off: no assist (neither the input nor the boost curve).

#include "model/solver/mechanical_block.h"
#include "model/vehicle/vehicle_inputs.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle {

class Steering final : public solver::MechanicalBlock<2> {
 public:
  /// Its coordinates and speeds are state.steering_y, steering_z; it reads the driver's and the
  /// assist inputs and the rack force of the wheels (workspace).
  Steering(const SteeringParams& p, VehicleState& state, const VehicleInputs& inputs,
           const VehicleWorkspace& work);
  [[nodiscard]] Eigen::Index size() const noexcept override { return 2; }
  [[nodiscard]] Vector& coordinates() noexcept override { return state_.steering_y; }
  [[nodiscard]] Vector& speeds() noexcept override { return state_.steering_z; }
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;
  /// Torsion bar torque at a state [N m].
  [[nodiscard]] double torsion_bar_torque_nm(const Vector& y, const Vector& z) const noexcept;
  /// Assist torque for a torsion bar torque (input signal or boost curve; 0 with the ignition
  /// off) [N m].
  [[nodiscard]] double assist_torque_nm(double torsion_bar_nm) const noexcept;

 private:
  const SteeringParams& p_;
  VehicleState& state_;
  const VehicleInputs& inputs_;
  const VehicleWorkspace& work_;
};

}  // namespace rig::model::vehicle
