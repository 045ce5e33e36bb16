#pragma once
/// @file
/// The coupled step of a chain of units (eqs. 45-50), specialized for vehicle joints: the
/// joints act on the chassis coordinates only and K^-1 is block diagonal (chassis block, hub
/// identity), so the Newton iteration on lambda runs on the 6 chassis coordinates of each unit
/// with fixed-capacity matrices (no N x N products as in the generic solver::CoupledStepper):
///   J_j = dg/dy_j K_j^-1                         (m x 6, at y(k))
///   mu_j = chassis rows of M_VIj^-1 [J_j^T; 0]   (eq. 46, the unit's own factorization;
///                                                 = S_j^-1 J_j^T, S_j its chassis Schur
///                                                 complement: solve_mass_leading)
///   y_j(lambda) = y_uj + W_j lambda,  y_uj = y_j + h K_j^-1 (z_j + h z^u_j),
///   W_j = h^2 K_j^-1 mu_j                        (chassis rows, eqs. 45, 50)
///   lambda <- lambda - [sum_j dg/dy_j W_j]^-1 g  (eqs. 47-49), warm-started,
/// stopped on |g| and on the lambda increment as solver::ConstraintNewton (accurate forces);
/// then dz_j = M_VIj^-1 [J_j^T lambda; 0], one full solve per unit.
/// Construction allocates; step() never does.

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "model/combination/begin_step_runner.h"
#include "model/combination/chain_constraint.h"
#include "model/report.h"
#include "model/solver/constraint_coupling.h"
#include "model/solver/couplable_system.h"

namespace rig::model::combination {

class ChainStepper {
 public:
  static constexpr int kMaxRows = kMaxJoints * JointEvaluation::kMaxRows;
  using RowVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRows, 1>;
  using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRows, kMaxRows>;
  using ChassisMatrix = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxRows>;
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;

  /// units in chain order (not owned); parallel (optional, not owned) runs begin_step of units
  /// 1..N-1 while the caller runs unit 0.
  ChainStepper(std::vector<solver::CouplableSystem*> units, const ChainConstraint& constraint,
               solver::NewtonParams params, BeginStepRunner* parallel = nullptr);

  /// Advances every unit by h with the joints closed at t + h.
  solver::NewtonReport step(double h) noexcept;

  [[nodiscard]] const RowVector& multipliers() const noexcept { return lambda_; }
  void set_multipliers(const Eigen::Ref<const Eigen::VectorXd>& lambda) noexcept {
    lambda_ = lambda;
    cache_valid_ = false;  // a reset or a reverted step: the cached dg/dy is stale
  }
  [[nodiscard]] const solver::NewtonReport& last_report() const noexcept { return report_; }
  [[nodiscard]] const solver::NewtonParams& params() const noexcept { return params_; }
  void set_params(const solver::NewtonParams& p) noexcept { params_ = p; }

 private:
  /// g and dg/dy (cache_) at y_j = y_uj + W_j lambda.
  void evaluate() noexcept;
  /// The Newton matrix sum_j dg/dy_j W_j from the dg/dy of the last evaluate().
  void assemble_newton_matrix() noexcept;

  std::vector<solver::CouplableSystem*> units_;
  const ChainConstraint& constraint_;
  solver::NewtonParams params_;
  BeginStepRunner* parallel_;
  Eigen::Index m_;
  RowVector lambda_, g_, d_lambda_;
  RowMatrix newton_matrix_;
  Eigen::PartialPivLU<RowMatrix> lu_;
  std::vector<ChassisMatrix> b_, mu_;      // per unit: J_j^T and its response, 6 x m
  std::vector<Eigen::VectorXd> rhs_, dz_;  // per unit: [J_j^T lambda; 0] and dz_j, n_j
  std::vector<Vector6> y_u_, y_;           // chassis coordinates
  std::vector<ChassisMatrix> w_;           // 6 x m
  /// dg/dy of every joint at the last Newton iterate = y(k+1) of the last step, reused as the
  /// dg/dy at y(k) of the next step (one joint evaluation less per step).
  std::array<JointEvaluation, kMaxJoints> cache_{};
  bool cache_valid_ = false;
  solver::NewtonReport report_;
};

}  // namespace rig::model::combination
