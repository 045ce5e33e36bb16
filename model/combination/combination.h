#pragma once
/// @file
/// A vehicle combination (issue 7): N separately modelled vehicles (tractor, trailers, dollies)
/// in a chain, joined by constraints and stepped as an index-3 DAE by the modified implicit Euler
/// with Newton on the stacked multipliers (eqs. 45-50, ChainStepper):
///   1. every unit runs its own force elements, subsystems and framework up to z^u and the
///      factorization of its M_VI (eq. 46) - independently, optionally in parallel threads;
///   2. Newton on lambda (eqs. 47-49), warm-started from the previous step, stopped on |g| AND on
///      the relative lambda increment (accurate joint forces, see constraint_coupling.h);
///   3. every unit finishes with dz = mu lambda (eq. 45).
/// No Baumgarte parameters, no coupled matrix of the whole combination.

#include <memory>
#include <string>
#include <vector>

#include "model/combination/begin_step_runner.h"
#include "model/combination/chain_constraint.h"
#include "model/combination/chain_stepper.h"
#include "model/combination/joint.h"
#include "model/stepped_model.h"
#include "model/vehicle/vehicle_model.h"

namespace rig::model::combination {

/// Newton settings of the combinations: |g| <= 1e-7 m (or rad) and the last lambda increment
/// below 1e-3 of |lambda| + 1 N (joint forces to 0.1 %).
solver::NewtonParams default_combination_newton_params() noexcept;

struct CombinationParams {
  std::string name;
  /// Leading unit first. A trailer is a vehicle without steered and driven axles.
  std::vector<vehicle::VehicleParams> units;
  /// joints[i] couples units[i] and units[i+1].
  std::vector<JointParams> joints;
  solver::NewtonParams newton = default_combination_newton_params();
  /// Run begin_step of units 1..N-1 with begin_step_runner while unit 0 runs on the caller's
  /// thread; parallel = true needs a runner (the rig's: make_thread_begin_step_runner).
  bool parallel = false;
  BeginStepRunnerFactory begin_step_runner;
};

/// A joint at a point `height_m` above the ground in the design position, `leading_x_m` from
/// the leading unit's CG and `trailing_x_m` from the trailing unit's (x forward).
JointParams make_joint_params(JointKind kind, const vehicle::VehicleParams& leading,
                              double leading_x_m, const vehicle::VehicleParams& trailing,
                              double trailing_x_m, double height_m);

/// Builds the units back to front so that each spring preload includes the static hitch loads
/// (ChassisParams supported / payload). Allocates.
std::vector<std::unique_ptr<vehicle::VehicleModel>> build_units(const CombinationParams& params,
                                                                double step_size_s);

/// Places the units in line behind unit 0 at (x, y, yaw), at rest, hitch points coinciding (tow
/// bar: the rod straight back, at its length).
void place_units(std::vector<std::unique_ptr<vehicle::VehicleModel>>& units,
                 const std::vector<JointParams>& joints, double x_m, double y_m, double yaw_rad);

class Combination final : public SteppedModel {
 public:
  Combination(const CombinationParams& params, double step_size_s);
  ~Combination() override;

  [[nodiscard]] double step_size_s() const noexcept override { return h_; }
  [[nodiscard]] double time_s() const noexcept override { return time_s_; }
  /// All units read the same inputs (trailer brakes follow their axles' brake circuits); the
  /// outputs are the leading unit's.
  StepStatus step(Signals& signals) noexcept override;
  void fill_report(ModelReport& report) const noexcept override;

  // ---- for tests and tools ----
  void reset(double x_m, double y_m, double yaw_rad) noexcept;
  void set_forward_speed(double speed_mps) noexcept;
  [[nodiscard]] int unit_count() const noexcept { return static_cast<int>(units_.size()); }
  [[nodiscard]] vehicle::VehicleModel& unit(int i) noexcept {
    return *units_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] const ChainConstraint& constraint() const noexcept { return *constraint_; }
  /// Newton report of the last step (iterations, residual |g|_inf).
  [[nodiscard]] const solver::NewtonReport& last_newton() const noexcept {
    return stepper_->last_report();
  }
  /// Stacked multipliers; joint i's force on its leading unit is lambda.segment<3>(row(i)).
  [[nodiscard]] const ChainStepper::RowVector& multipliers() const noexcept {
    return stepper_->multipliers();
  }
  /// Joint i's force on its leading unit, road frame [N] (tow bar: along the rod).
  [[nodiscard]] Vec3 joint_force_n(int i) const noexcept;
  /// Tow bar joint i: the rod force, tension positive [N]; 0 for the other joints.
  [[nodiscard]] double rod_force_n(int i) const noexcept;
  /// |g|_inf of joint i at the current coordinates [m].
  [[nodiscard]] double joint_violation_m(int i) const noexcept;
  /// Articulation angle (yaw of unit i minus yaw of unit i+1) [rad], wrapped to (-pi, pi].
  [[nodiscard]] double articulation_rad(int i) const noexcept;
  [[nodiscard]] ChainStepper& stepper() noexcept { return *stepper_; }

 private:
  CombinationParams p_;
  double h_;
  double time_s_ = 0;
  std::vector<std::unique_ptr<vehicle::VehicleModel>> units_;
  std::unique_ptr<BeginStepRunner> parallel_;
  std::unique_ptr<ChainConstraint> constraint_;
  std::unique_ptr<ChainStepper> stepper_;
  Eigen::VectorXd saved_lambda_, static_lambda_;
};

}  // namespace rig::model::combination
