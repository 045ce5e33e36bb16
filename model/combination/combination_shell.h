#pragma once
/// @file
/// What every vehicle combination shares, whichever way its joints are solved (the index-3 DAE
/// of eqs. 45-50 in Combination, the stiff spring-dampers of eqs. 32-38 in
/// ForceCoupledCombination): the units built back to front with their static hitch loads, their
/// placement in line, the step's frame (all units read the same inputs, a unit that fails undoes
/// the whole step, the outputs are the leading unit's), and the report of units and joints.

#include <memory>
#include <string>
#include <vector>

#include "model/combination/begin_step_runner.h"
#include "model/combination/chain_constraint.h"
#include "model/combination/joint.h"
#include "model/solver/constraint_coupling.h"
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

class CombinationShell : public SteppedModel {
 public:
  [[nodiscard]] double step_size_s() const noexcept override { return h_; }
  [[nodiscard]] double time_s() const noexcept override { return time_s_; }
  /// All units read the same inputs, each its own block of slots (model/signals.h): its
  /// wheels' pressures, else its circuits, else the enum's circuits by its axles' brake_circuit;
  /// the outputs are the leading unit's. A failed unit or coupling undoes the step in every unit;
  /// the fault is the first failed unit's (with its index), else the coupling's (unit -1).
  StepStatus step(Signals& signals) noexcept final;
  [[nodiscard]] ModelFault last_fault() const noexcept final { return fault_; }
  void fill_report(ModelReport& report) const noexcept final;

  // ---- for tests and tools ----
  /// The units in line behind unit 0 at (x, y, yaw), at rest, hitch points coinciding (tow bar:
  /// the rod straight back, at its length); the coupling at its static state.
  void reset(double x_m, double y_m, double yaw_rad) noexcept;
  void set_forward_speed(double speed_mps) noexcept;
  /// The start in equilibrium of the whole chain (model/vehicle/vehicle_equilibrium.h): at rest
  /// with every brake holding, or at a forward speed in line with the throttle found that holds
  /// it (the leading unit's a_x); every unit back at its pose, the clock at 0. Before the loop.
  vehicle::Equilibrium settle(double speed_mps, int gear_request = 99);
  [[nodiscard]] int unit_count() const noexcept { return static_cast<int>(units_.size()); }
  [[nodiscard]] vehicle::VehicleModel& unit(int i) noexcept {
    return *units_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] const ChainConstraint& constraint() const noexcept { return *constraint_; }
  /// Joint i's force on its leading unit, road frame [N].
  [[nodiscard]] virtual Vec3 joint_force_n(int i) const noexcept = 0;
  /// |g|_inf of joint i at the current coordinates [m] (the spring's deflection when force
  /// coupled).
  [[nodiscard]] double joint_violation_m(int i) const noexcept;
  /// Articulation angle (yaw of unit i minus yaw of unit i+1) [rad], wrapped to (-pi, pi].
  [[nodiscard]] double articulation_rad(int i) const noexcept;

 protected:
  /// Builds the units back to front so that each spring preload includes the static hitch
  /// loads (ChassisParams supported / payload), and the chain constraint. Allocates.
  CombinationShell(const CombinationParams& params, double step_size_s);

  /// One coupled step of every unit from set inputs; false if the coupling itself failed.
  virtual bool couple(double h) noexcept = 0;
  /// The coupling's own state back to before the failed step.
  virtual void revert_coupling() noexcept {}
  /// The coupling's state for units at rest (reset()).
  virtual void reset_coupling() noexcept = 0;
  /// Tow bar joint i: the rod force, tension positive [N]; 0 elsewhere.
  [[nodiscard]] virtual double rod_force_n(int i) const noexcept {
    (void)i;
    return 0;
  }
  /// Newton iterations of the last step (0: no Newton).
  [[nodiscard]] virtual int newton_iterations() const noexcept { return 0; }

  CombinationParams p_;
  double h_;
  double time_s_ = 0;
  ModelFault fault_{};
  std::vector<std::unique_ptr<vehicle::VehicleModel>> units_;
  std::unique_ptr<ChainConstraint> constraint_;

 private:
  /// The step's fault: the first unit that failed, else the coupling if it did, else none.
  [[nodiscard]] ModelFault first_fault(bool coupled) const noexcept;
};

}  // namespace rig::model::combination
