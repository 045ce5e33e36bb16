#pragma once
/// @file
/// The vehicle's blocks and their steppers, built once from the parameters (allocates) and wired
/// to the one state, the step's inputs and the workspace; the sequential stepper runs them in the
/// order of eq. (8): the tires' and half shafts' force elements, the drive train, the steering
/// and the wheel spins, then the framework (chassis + hub travel) with the arrowhead
/// factorization of eqs. (30-31). A unit without driven axles (a trailer) has no drive-train
/// stages, one without steered axles no steering stage (their states stay at rest).

#include <memory>
#include <variant>
#include <vector>

#include "model/solver/arrowhead_factorization.h"
#include "model/solver/force_element_stepper.h"
#include "model/solver/mechanical_stepper.h"
#include "model/solver/sequential_stepper.h"
#include "model/tire/tmeasy_force_element.h"
#include "model/vehicle/differential/differential_shafts.h"
#include "model/vehicle/drivetrain.h"
#include "model/vehicle/free_body/free_bodies.h"
#include "model/vehicle/half_shafts.h"
#include "model/vehicle/leaf_axle.h"
#include "model/vehicle/leaf_balance.h"
#include "model/vehicle/steering/column_steering.h"
#include "model/vehicle/steering/enhanced_steering.h"
#include "model/vehicle/steering/simple_steering.h"
#include "model/vehicle/steering/steer_by_wire.h"
#include "model/vehicle/suspension_kinematics.h"
#include "model/vehicle/vehicle_framework.h"
#include "model/vehicle/wheel_spin.h"

namespace rig::model::vehicle {

/// The driven wheels (front to rear) and how many there are.
struct DrivenWheels {
  std::array<int, kMaxWheels> wheel{};
  int count = 0;
};
[[nodiscard]] DrivenWheels driven_wheels(const VehicleParams& p) noexcept;

class VehicleBlocks {
 public:
  /// p, state, inputs and work must outlive the blocks (they belong to the VehicleModel).
  VehicleBlocks(const VehicleParams& p, VehicleState& state, const VehicleInputs& inputs,
                VehicleWorkspace& work);
  VehicleBlocks(const VehicleBlocks&) = delete;
  VehicleBlocks& operator=(const VehicleBlocks&) = delete;

  /// The start of a step: eq. (29) at y_V(k), then every wheel's contact - vertical force,
  /// rolling radius, the tire's characteristic at F_z and mu and f(s) (frozen over the step).
  /// On a road that is not the plane, first each wheel's local road plane, centred where the
  /// wheel is `lookahead_s` on (the step h: the step evaluates q at y(k) + h K^-1 z(k), eqs. 6-7;
  /// 0 for the outputs of a state as it is).
  void update_contacts(double lookahead_s) noexcept;
  /// The outputs of the current state: every wheel's forces, the torsion bar, assist and engine
  /// torque (workspace).
  void update_outputs() noexcept;

  [[nodiscard]] solver::SequentialStepper& sequence() noexcept { return sequence_; }
  [[nodiscard]] const solver::SequentialStepper& sequence() const noexcept { return sequence_; }
  [[nodiscard]] VehicleFramework& framework() noexcept { return framework_; }
  [[nodiscard]] const VehicleFramework& framework() const noexcept { return framework_; }
  /// The steering's block, whichever `[steering] model` built: the simple model's 2 DOF (its
  /// coordinates are state.steering_y, steering_z) or the enhanced model's system + knuckles.
  /// Exactly one alternative, never null.
  using SteeringBlock = std::variant<SimpleSteering*, EnhancedSteering*>;
  [[nodiscard]] SteeringBlock steering_block() noexcept {
    if (enhanced_steering_) return enhanced_steering_.get();
    return simple_steering_.get();
  }
  /// The rack side's system (sec. 2.2): begin_step before the implicit step, report values.
  [[nodiscard]] SteeringSystem& steering_system() noexcept { return *steering_system_; }
  [[nodiscard]] const Drivetrain& drivetrain() const noexcept { return drivetrain_; }
  /// The free bodies (`[[free_body]]`); null without any.
  [[nodiscard]] FreeBodies* free_bodies() noexcept { return free_bodies_.get(); }
  /// The leaf-sprung rigid axles' elements (leaf_axle.h), in axle order; a reset puts each
  /// one's state at rest.
  [[nodiscard]] const std::vector<std::unique_ptr<LeafAxleSuspension>>& leaf_axles()
      const noexcept {
    return leaf_axles_;
  }
  void place_leaf_axles_at_rest() const noexcept {
    for (const auto& l : leaf_axles_) l->place_at_rest();
    for (const auto& b : leaf_balances_) b->place_at_rest();
  }
  /// The leaf balances (`[[load_sharing]] kind = "leaf_balance"`, leaf_balance.h).
  [[nodiscard]] const std::vector<std::unique_ptr<LeafBalance>>& leaf_balances() const noexcept {
    return leaf_balances_;
  }
  /// The framework's stepper: M_VI and q of the step (for the force-coupled combination).
  [[nodiscard]] const solver::MechanicalStepper<Eigen::Dynamic, solver::ArrowheadFactorization>&
  framework_stepper() const noexcept {
    return framework_stepper_;
  }

 private:
  const VehicleParams& p_;
  VehicleState& state_;
  const VehicleInputs& inputs_;
  VehicleWorkspace& work_;
  SuspensionKinematics kinematics_;
  VehicleFramework framework_;
  std::unique_ptr<HalfShafts> shafts_;  ///< none without driven wheels or with differentials
  /// [[drivetrain.differential]] configured (and driven wheels): the tree instead of shafts_
  std::unique_ptr<differential::DifferentialShafts> differentials_;
  DrivenShafts* driven_shafts_;  ///< the one of the two, or none
  Drivetrain drivetrain_;
  std::unique_ptr<SteeringSystem> steering_system_;
  std::unique_ptr<SimpleSteering> simple_steering_;      ///< [steering] model = "simple"
  std::unique_ptr<EnhancedSteering> enhanced_steering_;  ///< model = "enhanced"
  WheelSpinStage wheel_stage_;
  std::vector<std::unique_ptr<tire::TmeasyForceElement>> tires_;
  std::vector<std::unique_ptr<solver::ForceElementStepper<2>>> tire_steppers_;
  std::unique_ptr<solver::ForceElementStepper<Eigen::Dynamic>> shaft_stepper_;
  solver::MechanicalStepper<2> drivetrain_stepper_;
  std::unique_ptr<solver::Stage> steering_stage_;                ///< the stepper of one of the two
  std::unique_ptr<FreeBodies> free_bodies_;                      ///< none without [[free_body]]
  std::vector<std::unique_ptr<LeafAxleSuspension>> leaf_axles_;  ///< [axle.leaf_spring]
  std::vector<std::unique_ptr<LeafBalance>> leaf_balances_;      ///< rockers between leaves
  /// The leaf balances of `p` over the leaf axles built (construction time).
  void build_leaf_balances(const VehicleParams& p, VehicleState& state);
  solver::MechanicalStepper<Eigen::Dynamic, solver::ArrowheadFactorization> framework_stepper_;
  solver::SequentialStepper sequence_;
};

}  // namespace rig::model::vehicle
