#pragma once
/// @file
/// Constraint coupling of separately modelled systems (eqs. 39-50): the index-3 DAE
/// 0 = g(y_1, ..., y_n) solved directly by Newton on the multipliers lambda.
///
/// With every system's z^u and mu_j = M_VIj^-1 (dg/dy_j K_j^-1)^T (eq. 46), the new coordinates
/// are linear in lambda (eq. 45):
///   Y(lambda) = Y_u + W lambda,  Y_u = Y(k) + h K^-1 (Z(k) + h Z^u),  W = h^2 K^-1 Mu,
/// where Y stacks all systems' coordinates. Newton on g(Y(lambda)) = 0 (eqs. 47-50):
///   lambda_(i+1) = lambda_i - [dg/dY(Y_i) W]^-1 g(Y_i),
/// started at the previous step's lambda.
///
/// Convergence criterion (why both tests by default): g is a position error. At h = 1 ms, a
/// lambda error d_lambda moves the coordinates only by about h^2 mu d_lambda - for the
/// pendulums ~1e-7 m per 1 N - so a loose position tolerance (even 0.1 mm) accepts a lambda
/// that is off by hundreds of newtons: |g| looks fine while the constraint force is badly wrong
/// (and the next step inherits the error in z). kPositionAndMultiplier therefore also demands
/// that the last Newton increment be small relative to |lambda|:
///   |g|_inf <= position_tolerance  and  |d_lambda|_inf <= multiplier_rel_tolerance |lambda|_inf
///                                                     + multiplier_abs_tolerance.
/// Newton converges quadratically, so the increment test costs at most one extra iteration.

#include <Eigen/Core>
#include <Eigen/LU>

#include "model/solver/couplable_system.h"

namespace rig::model::solver {

/// Constraint functions 0 = g(Y) over the stacked coordinates Y = [y_1; y_2; ...] of the
/// coupled systems (in the order they are given to CoupledStepper). Called in the RT path.
class ConstraintFunction {
 public:
  ConstraintFunction() = default;
  ConstraintFunction(const ConstraintFunction&) = delete;
  ConstraintFunction& operator=(const ConstraintFunction&) = delete;
  virtual ~ConstraintFunction() = default;

  /// Number of constraints (= size of lambda).
  [[nodiscard]] virtual Eigen::Index size() const noexcept = 0;
  /// g(Y) and dg/dY (size() x Y.size()) at Y. No allocation.
  virtual void evaluate(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> g,
                        Eigen::Ref<Eigen::MatrixXd> dg_dy) const noexcept = 0;
};

/// When the Newton loop stops (see the file comment for why the default is what it is).
enum class NewtonCriterion {
  kPosition,               ///< |g| only (cheap, but leaves lambda wrong at small h)
  kPositionAndMultiplier,  ///< |g| and the relative lambda increment (default)
};

struct NewtonParams {
  NewtonCriterion criterion = NewtonCriterion::kPositionAndMultiplier;
  double position_tolerance = 1e-7;        ///< on |g|_inf [m or rad]
  double multiplier_rel_tolerance = 1e-6;  ///< on |d_lambda|_inf / |lambda|_inf
  double multiplier_abs_tolerance = 1e-6;  ///< [N] floor for lambda near zero
  int max_iterations = 10;                 ///< cap; the step is taken anyway, flagged
};

/// What the Newton loop did in one step.
struct NewtonReport {
  int iterations = 0;         ///< linear solves of eq. (48)
  double residual = 0;        ///< |g(Y(lambda))|_inf at the returned lambda
  double last_increment = 0;  ///< |d_lambda|_inf of the last iteration
  bool converged = false;     ///< false: the cap was reached
};

/// The one stopping rule of the Newton loops on lambda (ConstraintNewton here, the combinations'
/// ChainStepper): with `report` holding |g| of the current iterate and, after the first
/// iteration, the last increment, the iterate is accepted under the params' criterion (see the
/// file comment). The warm start (no iteration yet) is accepted on |g| only under kPosition: its
/// lambda has not been checked by an increment.
template <typename Lambda>
[[nodiscard]] bool newton_converged(const NewtonParams& params, const NewtonReport& report,
                                    const Eigen::MatrixBase<Lambda>& lambda) noexcept {
  const bool position_ok = report.residual <= params.position_tolerance;
  if (params.criterion == NewtonCriterion::kPosition) return position_ok;
  if (report.iterations == 0) return false;
  return position_ok && report.last_increment <= params.multiplier_rel_tolerance *
                                                         lambda.template lpNorm<Eigen::Infinity>() +
                                                     params.multiplier_abs_tolerance;
}

/// Newton on lambda (eqs. 47-50) for given Y_u and W. Sized in the constructor; solve() never
/// allocates.
class ConstraintNewton {
 public:
  ConstraintNewton(const ConstraintFunction& constraint, Eigen::Index coordinate_size,
                   NewtonParams params);

  /// lambda: in the warm start, out the solution. Y_u: coordinate_size; W: coordinate_size x
  /// constraint size.
  NewtonReport solve(const Eigen::Ref<const Eigen::VectorXd>& y_u,
                     const Eigen::Ref<const Eigen::MatrixXd>& w,
                     Eigen::Ref<Eigen::VectorXd> lambda) noexcept;

  [[nodiscard]] const NewtonParams& params() const noexcept { return params_; }
  void set_params(const NewtonParams& params) noexcept { params_ = params; }

 private:
  const ConstraintFunction& constraint_;
  NewtonParams params_;
  Eigen::VectorXd y_, g_, d_lambda_;
  Eigen::MatrixXd dg_dy_, dg_dlambda_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace rig::model::solver
