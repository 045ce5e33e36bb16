#pragma once
/// @file
/// The generic vehicle: framework (chassis + hub travel), TMeasy tires with first-order
/// dynamics, wheel spins with implicit dry-friction brakes, rack-and-pinion steering with torsion
/// bar and assist, engine / converter / gearbox / open differentials / compliant half shafts;
/// advanced by the modified implicit Euler in the order of eq. (8). Parameters (VehicleParams),
/// the one state (VehicleState), the step's inputs (VehicleInputs) and the workspace are apart;
/// the blocks (VehicleBlocks) refer to them.

#include <memory>

#include "model/solver/couplable_system.h"
#include "model/stepped_model.h"
#include "model/vehicle/vehicle_blocks.h"
#include "model/vehicle/vehicle_equilibrium.h"
#include "model/vehicle/vehicle_faults.h"
#include "model/vehicle/vehicle_inputs.h"
#include "model/vehicle/vehicle_state.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle {

/// A SteppedModel on its own; as a solver::CouplableSystem one unit of a vehicle combination
/// (model/combination): set_inputs(), then begin_step() runs the force elements, subsystems and
/// the framework up to z^u and the factorization of M_VI (eq. 46), and finish_step() applies the
/// constraint response dz = mu lambda (eq. 45). step() is set_inputs + begin_step +
/// finish_step(0) + write_outputs.
class VehicleModel final : public SteppedModel, public solver::CouplableSystem {
 public:
  /// Builds every block and workspace (allocates); throws std::invalid_argument on parameters
  /// the model cannot run (fewer than one axle, more than kMaxWheels wheels, h <= 0, a unit
  /// index outside 0..kMaxUnits-1). unit_index: its place in a combination (0: the leading unit
  /// or a vehicle on its own), which selects its input slots (model/signals.h).
  VehicleModel(const VehicleParams& params, double step_size_s, int unit_index = 0);
  ~VehicleModel() override;

  [[nodiscard]] double step_size_s() const noexcept override { return h_; }
  [[nodiscard]] double time_s() const noexcept override { return state_.time_s; }
  StepStatus step(Signals& signals) noexcept override;
  /// The fault of the last step (vehicle_faults.h), unit 0; kind kNone after a good step.
  [[nodiscard]] ModelFault last_fault() const noexcept override { return fault_; }
  void fill_report(ModelReport& report) const noexcept override;

  // ---- CouplableSystem: one unit of a combination (eqs. 45-46) ----
  void set_inputs(const Signals& signals) noexcept;
  [[nodiscard]] Eigen::Index coordinate_size() const noexcept override;
  /// Gear selection, contacts, then eq. (8) up to z^u of the framework (h = step_size_s()).
  void begin_step(double h) noexcept override;
  [[nodiscard]] ConstVectorRef coordinates() const noexcept override;
  [[nodiscard]] ConstVectorRef speeds() const noexcept override;
  [[nodiscard]] ConstMatrixRef kinematics_inverse() const noexcept override;
  [[nodiscard]] ConstVectorRef unconstrained_rate() const noexcept override;
  void solve_mass(ConstMatrixRef b, MatrixRef x) const noexcept override;
  /// For the 6 chassis rows: S^-1 b with the Schur complement of the hub blocks.
  void solve_mass_leading(ConstMatrixRef b, MatrixRef x) const noexcept override;
  /// z(k+1) = z(k) + h (z^u + extra_rate), y(k+1) = ... (eq. 45), then the step's outputs. On a
  /// fault (FaultCheck: non-finite, or beyond a limit) the step is undone before any output is
  /// written (last_status() kNonFinite or kVehicleFault, last_fault() says what).
  void finish_step(double h, ConstVectorRef extra_rate) noexcept override;
  [[nodiscard]] StepStatus last_status() const noexcept { return last_status_; }
  /// Undoes the last completed step, e.g. when another unit of the same combination failed in
  /// it. Only once per step.
  void revert_step() noexcept;
  /// M_VI of the framework and q at the predicted coordinates, valid after begin_step(); for the
  /// force-coupled baseline that assembles one big implicit matrix (eqs. 32-38).
  [[nodiscard]] const Eigen::MatrixXd& modified_mass_matrix() const noexcept;
  [[nodiscard]] const Eigen::VectorXd& applied_forces() const noexcept;
  /// Writes the output signals of the current state (step() calls it).
  void write_outputs(Signals& s) const noexcept;

  // ---- for tests and tools ----
  [[nodiscard]] const VehicleParams& params() const noexcept { return p_; }
  [[nodiscard]] int unit_index() const noexcept { return unit_; }
  [[nodiscard]] const VehicleState& state() const noexcept { return state_; }
  [[nodiscard]] const VehicleWorkspace& workspace() const noexcept { return work_; }
  [[nodiscard]] VehicleFramework& framework() noexcept { return blocks_->framework(); }
  [[nodiscard]] const VehicleFramework& framework() const noexcept { return blocks_->framework(); }
  /// The steering block of the configured model (VehicleBlocks::steering_block: the simple or
  /// the enhanced one, never null).
  [[nodiscard]] VehicleBlocks::SteeringBlock steering_block() noexcept {
    return blocks_->steering_block();
  }
  /// Vertical tire force of wheel i after the last step [N].
  [[nodiscard]] double wheel_load_n(int i) const noexcept;
  /// At rest at the design position with the engine idling, at (x, y, yaw).
  void reset(double x_m, double y_m, double yaw_rad) noexcept;
  /// Sets the forward speed (chassis, wheel spins, drive train consistent), for maneuver starts.
  void set_forward_speed(double speed_mps) noexcept;
  /// The start in equilibrium (vehicle_equilibrium.cpp): relaxes every state but the pose to its
  /// steady value - at rest the static suspension and tire deflections (settled with the brakes
  /// holding, in neutral), at a forward speed the steady rolling state (wheel spins, tire
  /// deflections, gear, engine and converter) with the chassis speed held and the throttle found
  /// that holds it - then puts the vehicle back at its pose with the clock at 0. Allocation-free;
  /// runs some thousand steps (construction time, before the loop).
  /// gear_request: the gear the run starts in (99 automatic), used when rolling.
  using Equilibrium = vehicle::Equilibrium;
  Equilibrium settle(double speed_mps, int gear_request = 99) noexcept;
  /// settle()'s stages, for a combination's units (CombinationShell::settle): the pose to come
  /// back to (rolling: the forward speed set); the in-plane motion held after each step (speed
  /// v, no lateral speed, no yaw rate; heave, pitch and roll settle freely); back at the pose
  /// with the clock at 0 and the motion as held.
  struct Pose {
    double x_m = 0, y_m = 0, yaw_rad = 0;
  };
  Pose begin_settle(double speed_mps) noexcept;
  /// lateral_mps: the CG's lateral speed (body axes) to hold instead of 0 - a trailing unit's,
  /// so that its joint point moves with the leading unit's (combination_hold.h).
  void hold_plane_motion(double speed_mps, double lateral_mps = 0.0) noexcept;
  void end_settle(const Pose& pose, double speed_mps) noexcept;

 private:
  VehicleParams p_;
  double h_;
  int unit_;  ///< index in a combination: its input slots
  FaultCheck fault_check_;
  ModelFault fault_{};
  VehicleState state_;
  VehicleState saved_;  ///< the state at the start of the step (rollback, acceleration)
  VehicleInputs inputs_{};
  VehicleWorkspace work_{};
  std::unique_ptr<VehicleBlocks> blocks_;
  Eigen::VectorXd zero_rate_;
  StepStatus last_status_ = StepStatus::kOk;
};

}  // namespace rig::model::vehicle
