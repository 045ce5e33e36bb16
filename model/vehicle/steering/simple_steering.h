#pragma once
/// @file
/// The simple steering model (Fig. 7 left) as a 2-DOF block: a SteeringSystem loaded at the rack
/// by the tie rods' force of the wheel-spin stage (VehicleWorkspace::rack_force_n: the wheels'
/// moments on their steering axes by virtual work, quasi-static, from the last step).

#include "model/solver/mechanical_block.h"
#include "model/vehicle/steering/steering_system.h"
#include "model/vehicle/vehicle_state.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle {

class SimpleSteering final : public solver::MechanicalBlock<2> {
 public:
  /// Its coordinates and speeds are state.steering_y, steering_z.
  SimpleSteering(SteeringSystem& system, VehicleState& state, const VehicleWorkspace& work)
      : system_(system), state_(state), work_(work) {}
  [[nodiscard]] Eigen::Index size() const noexcept override { return 2; }
  [[nodiscard]] Vector& coordinates() noexcept override { return state_.steering_y; }
  [[nodiscard]] Vector& speeds() noexcept override { return state_.steering_z; }
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override {
    system_.mass_matrix(y, m);
  }
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override {
    system_.applied_forces(y, z, q);
    q(1) -= work_.rack_force_n;
    // the sticking bore torques' stiff part of it, linearized about where it was evaluated
    // (their twist follows the rack within the step), so the coupling is implicit
    if (work_.rack_bore_stiffness_npm != 0.0)
      q(1) -= work_.rack_bore_stiffness_npm * (y(1) - work_.rack_force_at_m);
  }
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override {
    system_.force_jacobians(y, z, dq_dy, dq_dz);
    // the sticking bore torques' partial (applied_forces)
    dq_dy(1, 1) -= work_.rack_bore_stiffness_npm;
    return true;
  }
  /// The system's friction on the wheel angle and the rack travel (stick-predicted).
  void dry_friction(const Vector& y, const Vector& z,
                    solver::FrictionSet<2>& contacts) const noexcept override {
    const SteeringFriction f = system_.dry_friction(y, z);
    contacts.clear();
    contacts.add_on_coordinate(0, f.column_nm);
    contacts.add_on_coordinate(1, f.rack_n);
  }

 private:
  SteeringSystem& system_;
  VehicleState& state_;
  const VehicleWorkspace& work_;
};

}  // namespace rig::model::vehicle
