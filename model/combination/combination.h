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

#include "model/combination/begin_step_runner.h"
#include "model/combination/chain_stepper.h"
#include "model/combination/combination_shell.h"

namespace rig::model::combination {

class Combination final : public CombinationShell {
 public:
  Combination(const CombinationParams& params, double step_size_s);
  ~Combination() override;

  /// Newton report of the last step (iterations, residual |g|_inf).
  [[nodiscard]] const solver::NewtonReport& last_newton() const noexcept {
    return stepper_->last_report();
  }
  /// Stacked multipliers; joint i's force on its leading unit is lambda.segment<3>(row(i)).
  [[nodiscard]] const ChainStepper::RowVector& multipliers() const noexcept {
    return stepper_->multipliers();
  }
  /// Joint i's force on its leading unit, road frame [N] (tow bar: along the rod).
  [[nodiscard]] Vec3 joint_force_n(int i) const noexcept override;
  /// Tow bar joint i: the rod force, tension positive [N]; 0 for the other joints.
  [[nodiscard]] double rod_force_n(int i) const noexcept override;
  [[nodiscard]] ChainStepper& stepper() noexcept { return *stepper_; }

 private:
  bool couple(double h) noexcept override;
  void revert_coupling() noexcept override;
  void reset_coupling() noexcept override;
  [[nodiscard]] int newton_iterations() const noexcept override {
    return stepper_->last_report().iterations;
  }

  std::unique_ptr<BeginStepRunner> parallel_;
  std::unique_ptr<ChainStepper> stepper_;
  Eigen::VectorXd saved_lambda_, static_lambda_;
};

}  // namespace rig::model::combination
