#pragma once
/// @file
/// The rack side of the steering (sec. 2.2, Fig. 7): a steering system with two coordinates
/// y = [steering wheel angle, rack travel u] and their speeds z, loaded at the rack by the tie
/// rods (their force F_S1 + F_S2 resists positive u). The model adds that force: the simple model
/// (SimpleSteering) as the wheels' moments on the steering axes by virtual work, lagged one step
/// (quasi-static tie rods); the enhanced model as the drag-link springs between rack and
/// knuckles, implicit with them. Implementations: ColumnSteering (column, torsion bar, EPS
/// assist, overriding gear). Parameters constant; the states live in VehicleState.

#include <Eigen/Core>

namespace rig::model::vehicle {

class SteeringSystem {
 public:
  using Vector = Eigen::Vector2d;
  using Matrix = Eigen::Matrix2d;

  SteeringSystem() = default;
  SteeringSystem(const SteeringSystem&) = delete;
  SteeringSystem& operator=(const SteeringSystem&) = delete;
  virtual ~SteeringSystem() = default;

  /// Once per step, before the implicit step: the system's own explicit states (the overriding
  /// gear's angle, an actuator's lag) follow their commands. Default: none.
  virtual void begin_step(double h) noexcept { (void)h; }
  /// M(y) of the two coordinates.
  virtual void mass_matrix(const Vector& y, Matrix& m) const noexcept = 0;
  /// q(y, z) without the tie rods' force on the rack.
  virtual void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept = 0;
  /// The stiff partials of applied_forces (method.md sec. 6).
  virtual void force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                               Matrix& dq_dz) const noexcept = 0;
  /// What the report shows at a state: the torsion bar's torque (0 without one) [N m] and the
  /// assist or actuator torque at the pinion [N m].
  [[nodiscard]] virtual double torsion_bar_torque_nm(const Vector& y,
                                                     const Vector& z) const noexcept = 0;
  [[nodiscard]] virtual double assist_torque_nm(const Vector& y,
                                                const Vector& z) const noexcept = 0;
};

}  // namespace rig::model::vehicle
