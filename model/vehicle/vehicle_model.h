#pragma once
/// @file
/// The generic vehicle (issue 6): framework (chassis + hub travel), TMeasy tires with
/// first-order dynamics, wheel spins with implicit dry-friction brakes, rack-and-pinion steering
/// with torsion bar and assist, engine / converter / gearbox / open differentials / compliant
/// half shafts; advanced by the modified implicit Euler engine in the order of eq. (8).

#include <array>
#include <memory>
#include <vector>

#include "model/solver/arrowhead_factorization.h"
#include "model/solver/couplable_system.h"
#include "model/solver/engine.h"
#include "model/solver/force_element_stepper.h"
#include "model/solver/mechanical_stepper.h"
#include "model/stepped_model.h"
#include "model/vehicle/drivetrain.h"
#include "model/vehicle/half_shafts.h"
#include "model/vehicle/steering.h"
#include "model/vehicle/suspension_kinematics.h"
#include "model/vehicle/tire_deflection.h"
#include "model/vehicle/vehicle_framework.h"
#include "model/vehicle/wheel_spin.h"

namespace rig::model::vehicle {

/// A SteppedModel on its own; as a solver::CouplableSystem it is one unit of a vehicle
/// combination (model/combination): set_inputs(), then begin_step() runs the force elements,
/// subsystems and the framework up to z^u and the factorization of M_VI (eq. 46), and
/// finish_step() applies the constraint response dz = mu lambda (eq. 45) and completes the step.
/// step() is exactly set_inputs + begin_step + finish_step(0) + write_outputs.
class VehicleModel final : public SteppedModel, public solver::CouplableSystem {
 public:
  /// Builds every block and workspace (allocates); throws std::invalid_argument on parameters
  /// the model cannot run (fewer than one axle, more than kMaxWheels wheels).
  VehicleModel(const VehicleParams& params, double step_size_s);
  ~VehicleModel() override;

  [[nodiscard]] double step_size_s() const noexcept override { return h_; }
  [[nodiscard]] double time_s() const noexcept override { return time_s_; }
  StepStatus step(Signals& signals) noexcept override;
  void fill_report(ModelReport& report) const noexcept override;

  // ---- CouplableSystem: one unit of a combination (eqs. 45-46) ----
  /// Reads the driver/ECU inputs for the next begin_step().
  void set_inputs(const Signals& signals) noexcept;
  [[nodiscard]] Eigen::Index coordinate_size() const noexcept override;
  /// Gear selection, contacts, then eq. (8) up to z^u of the framework (h must be step_size_s()).
  void begin_step(double h) noexcept override;
  [[nodiscard]] ConstVectorRef coordinates() const noexcept override;
  [[nodiscard]] ConstVectorRef speeds() const noexcept override;
  [[nodiscard]] ConstMatrixRef kinematics_inverse() const noexcept override;
  [[nodiscard]] ConstVectorRef unconstrained_rate() const noexcept override;
  void solve_mass(ConstMatrixRef b, MatrixRef x) const noexcept override;
  /// For the 6 chassis rows: S^-1 b with the Schur complement of the hub blocks.
  void solve_mass_leading(ConstMatrixRef b, MatrixRef x) const noexcept override;
  /// z(k+1) = z(k) + h (z^u + extra_rate), y(k+1) = ... (eq. 45); then the outputs of the step
  /// are updated. On a non-finite state the step is undone (see last_status()).
  void finish_step(double h, ConstVectorRef extra_rate) noexcept override;
  /// kNonFinite if the last finish_step() produced a NaN/inf (the state was restored).
  [[nodiscard]] StepStatus last_status() const noexcept { return last_status_; }
  /// Undoes the last completed step (state and time), e.g. when another unit of the same
  /// combination failed in it. Only once per step.
  void revert_step() noexcept;
  /// M_VI of the framework (eq. 8) and q at the predicted coordinates, valid after begin_step();
  /// for the force-coupled baseline that assembles one big implicit matrix (eqs. 32-38).
  [[nodiscard]] const Eigen::MatrixXd& modified_mass_matrix() const noexcept;
  [[nodiscard]] const Eigen::VectorXd& applied_forces() const noexcept;
  /// Writes the output signals of the current state (step() calls it).
  void write_outputs(Signals& s) noexcept;

  // ---- for tests and tools ----
  [[nodiscard]] const VehicleParams& params() const noexcept { return p_; }
  [[nodiscard]] const VehicleBus& bus() const noexcept { return bus_; }
  [[nodiscard]] VehicleFramework& framework() noexcept { return *framework_; }
  [[nodiscard]] Steering& steering() noexcept { return *steering_; }
  [[nodiscard]] Drivetrain& drivetrain() noexcept { return *drivetrain_; }
  /// Vertical tire force of wheel i after the last step [N].
  [[nodiscard]] double wheel_load_n(int i) const noexcept;
  /// Places the vehicle at rest at the design position with the engine idling, at (x, y, yaw).
  void reset(double x_m, double y_m, double yaw_rad) noexcept;
  /// Sets the forward speed (chassis, wheel spins, drivetrain consistent), for maneuver starts.
  void set_forward_speed(double speed_mps) noexcept;

 private:
  void read_inputs(const Signals& s) noexcept;
  void select_gear() noexcept;
  void update_contacts() noexcept;
  void save_state() noexcept;
  void restore_state() noexcept;
  [[nodiscard]] bool state_finite() const noexcept;

  VehicleParams p_;
  double h_;
  double time_s_ = 0;
  VehicleBus bus_{};
  int gear_request_ = 99;
  double last_shift_s_ = -1e9;
  std::array<int, kMaxWheels> axle_of_wheel_{};
  std::array<WheelForces, kMaxWheels> wheel_out_{};

  std::unique_ptr<SuspensionKinematics> kinematics_;  ///< eq. (29), evaluated in update_contacts
  std::unique_ptr<VehicleFramework> framework_;
  std::unique_ptr<HalfShafts> shafts_;
  std::unique_ptr<Drivetrain> drivetrain_;
  std::unique_ptr<Steering> steering_;
  std::vector<std::unique_ptr<TireDeflection>> tires_;
  std::vector<std::unique_ptr<solver::ForceElementStepper<2>>> tire_steppers_;
  std::unique_ptr<solver::ForceElementStepper<Eigen::Dynamic>> shaft_stepper_;
  std::unique_ptr<solver::MechanicalStepper<2>> drivetrain_stepper_;
  std::unique_ptr<solver::MechanicalStepper<2>> steering_stepper_;
  std::unique_ptr<WheelSpinStage> wheel_stage_;
  std::unique_ptr<solver::MechanicalStepper<Eigen::Dynamic, solver::ArrowheadFactorization>>
      framework_stepper_;
  std::unique_ptr<solver::Engine> engine_;

  // saved state for kNonFinite recovery and the acceleration output
  Eigen::VectorXd saved_y_, saved_z_, saved_shafts_;
  Eigen::Vector2d saved_dt_y_, saved_dt_z_, saved_st_y_, saved_st_z_;
  std::array<double, kMaxWheels> saved_spin_{};
  std::array<double, 2 * std::size_t{kMaxWheels}> saved_deflection_{};
  Vec3 accel_body_ = Vec3::Zero();
  Eigen::VectorXd zero_rate_;
  StepStatus last_status_ = StepStatus::kOk;
  Vec3 saved_accel_body_ = Vec3::Zero();
};

}  // namespace rig::model::vehicle
