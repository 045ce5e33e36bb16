#pragma once
/// @file
/// Rack-in-the-loop (issue 15 item 6): a real steering gear on load actuators is the steering
/// system. The rig takes its measured rack travel and speed and answers with the tie-rod forces
/// (SteeringReport::tie_rod_force_left_n/right_n, the wheels' steering-axis moments by virtual
/// work). The rack is a kinematic constraint here, not a dynamic body: begin_step prescribes
/// y = [u_m / i_SB, u_m], z = [v_m / i_SB, v_m] (the bench's steering wheel turns with the rack
/// through its real gear), and the step keeps them: no forces, no partials, and a mass so large
/// that the tie rods' force cannot move it (F h / m < 1e-9 m/s per step), so the implicit step
/// ends at u_m + h v_m, the measurement carried over the step, exactly. A spring-damper to the
/// measurement would lag it by F / k and ring at k / m; prescribing has neither.
/// Measurement invalid (not valid or not finite): the rack holds its last position at rest.

#include "model/vehicle/steering/steering_system.h"
#include "model/vehicle/vehicle_inputs.h"
#include "model/vehicle/vehicle_params.h"
#include "model/vehicle/vehicle_state.h"

namespace rig::model::vehicle {

class RackInTheLoop final : public SteeringSystem {
 public:
  /// The constraint's mass [kg] (and inertia [kg m^2]): the tie rods' force over a step moves
  /// it by F h^2 / m, below 1e-12 m for F < 1e5 N, h < 10 ms.
  static constexpr double kPrescribedMassKg = 1e12;

  RackInTheLoop(const SteeringParams& p, VehicleState& state, const VehicleInputs& inputs);
  void begin_step(double h) noexcept override;
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  void force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;
  /// No torsion bar, no assist on the rig's side (they are on the bench).
  [[nodiscard]] double torsion_bar_torque_nm(const Vector& y,
                                             const Vector& z) const noexcept override;
  [[nodiscard]] double assist_torque_nm(const Vector& y, const Vector& z) const noexcept override;

 private:
  const SteeringParams& p_;
  VehicleState& state_;
  const VehicleInputs& inputs_;
};

}  // namespace rig::model::vehicle
