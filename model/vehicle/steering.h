#pragma once
/// @file
/// The enhanced rack-and-pinion steering system (sec. 2.2) as a subsystem (eq. 2):
/// coordinates [steering wheel angle, rack travel u]. Steering wheel + column inertia, torsion
/// bar (its torque is what the assist senses), steering box ratio i_SB (rack travel per pinion
/// angle), rack mass, rack dry friction (regularized, its steep slope in M_VI keeps it stable),
/// assist torque on the pinion (input signal or built-in boost curve), and the tie-rod forces
/// from the wheels (VehicleBus::rack_force_n). The wheel is driven by hand torque or, in
/// angle mode, by a stiff position servo (a steering robot).

#include "model/solver/mechanical_block.h"
#include "model/vehicle/vehicle_bus.h"

namespace rig::model::vehicle {

class Steering final : public solver::MechanicalBlock<2> {
 public:
  Steering(VehicleBus& bus, const SteeringParams& p);
  [[nodiscard]] Eigen::Index size() const noexcept override { return 2; }
  [[nodiscard]] Vector& coordinates() noexcept override { return y_; }
  [[nodiscard]] Vector& speeds() noexcept override { return z_; }
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;
  /// Torsion bar torque at a state [N m].
  [[nodiscard]] double torsion_bar_torque_nm(const Vector& y, const Vector& z) const noexcept;
  /// Assist torque for a torsion bar torque (input signal or boost curve) [N m].
  [[nodiscard]] double assist_torque_nm(double torsion_bar_nm) const noexcept;

 private:
  VehicleBus& bus_;
  const SteeringParams& p_;
  Vector y_ = Vector::Zero();
  Vector z_ = Vector::Zero();
};

}  // namespace rig::model::vehicle
