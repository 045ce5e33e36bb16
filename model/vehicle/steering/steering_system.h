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

/// The dry-friction capacities of a steering system's two coordinates (>= 0; 0: none). The
/// steering block declares them to the stepper (solver/dry_friction.h), which solves them
/// stick-predicted, coupled through the mass matrix and the torsion bar: each sticks (speed
/// exactly 0) or slides at exactly its capacity. No regularised law in applied_forces.
struct SteeringFriction {
  double column_nm = 0;  ///< on the steering wheel angle: column bearings, upper column [N m]
  double rack_n = 0;     ///< on the rack travel u: rack guide, pinion, seals [N]
};

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
  /// The hook for dry friction: its capacities this step (constant or load dependent). Every
  /// system declares its own (a steer-by-wire's actuators, a bench rack's guide); a steering
  /// model forwards them to its stepper's block (SimpleSteering::dry_friction). Default: none.
  [[nodiscard]] virtual SteeringFriction dry_friction(const Vector& y,
                                                      const Vector& z) const noexcept {
    (void)y;
    (void)z;
    return {};
  }
};

}  // namespace rig::model::vehicle
