#pragma once
/// @file
/// One step of several separately modelled systems joined by constraints (eqs. 45-50): each
/// system computes z^u and mu independently, Newton finds lambda, each system finishes its step
/// with dz = mu lambda. Vehicle combinations (car + tow bar + trailer) use it with whole
/// vehicles (SequentialStepper) as systems and only add their constraint functions.

#include <vector>

#include <Eigen/Core>

#include "model/solver/constraint_coupling.h"
#include "model/solver/couplable_system.h"

namespace rig::model::solver {

class CoupledStepper {
 public:
  /// systems: in the order of the stacked coordinates Y seen by constraint. Pointers are not
  /// owned. Construction allocates all workspaces.
  CoupledStepper(std::vector<CouplableSystem*> systems, const ConstraintFunction& constraint,
                 NewtonParams params = {});

  /// Advances every system by h with the constraint enforced at t + h. Never allocates.
  NewtonReport step(double h) noexcept;

  /// The multipliers lambda of the last step (the warm start of the next). Their meaning is the
  /// constraint's: the generalized constraint force on system j is (dg/dy_j K_j^-1)^T lambda.
  [[nodiscard]] const Eigen::VectorXd& multipliers() const noexcept { return lambda_; }
  void set_multipliers(const Eigen::Ref<const Eigen::VectorXd>& lambda) noexcept {
    lambda_ = lambda;
  }
  [[nodiscard]] const NewtonReport& last_report() const noexcept { return report_; }
  /// The stacked coordinates Y of all systems (current).
  void stacked_coordinates(Eigen::Ref<Eigen::VectorXd> y) const noexcept;
  [[nodiscard]] Eigen::Index stacked_size() const noexcept { return total_; }
  [[nodiscard]] ConstraintNewton& newton() noexcept { return newton_; }

 private:
  std::vector<CouplableSystem*> systems_;
  std::vector<Eigen::Index> offsets_;
  const ConstraintFunction& constraint_;
  Eigen::Index total_ = 0;
  Eigen::Index n_lambda_ = 0;
  ConstraintNewton newton_;
  Eigen::VectorXd y_, y_u_, g_, lambda_, dz_;
  Eigen::MatrixXd dg_dy_, w_, b_, mu_;
  NewtonReport report_;
};

}  // namespace rig::model::solver
