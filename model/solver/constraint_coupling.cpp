#include "model/solver/constraint_coupling.h"

namespace rig::model::solver {

ConstraintNewton::ConstraintNewton(const ConstraintFunction& constraint,
                                   Eigen::Index coordinate_size, NewtonParams params)
    : constraint_(constraint),
      params_(params),
      y_(coordinate_size),
      g_(constraint.size()),
      d_lambda_(constraint.size()),
      dg_dy_(constraint.size(), coordinate_size),
      dg_dlambda_(constraint.size(), constraint.size()),
      lu_(constraint.size()) {}

NewtonReport ConstraintNewton::solve(const Eigen::Ref<const Eigen::VectorXd>& y_u,
                                     const Eigen::Ref<const Eigen::MatrixXd>& w,
                                     Eigen::Ref<Eigen::VectorXd> lambda) noexcept {
  NewtonReport report;
  for (;;) {
    // eq. (45): the coordinates are linear in lambda
    y_ = y_u;
    y_.noalias() += w * lambda;
    constraint_.evaluate(y_, g_, dg_dy_);
    report.residual = g_.lpNorm<Eigen::Infinity>();
    if (newton_converged(params_, report, lambda)) {
      report.converged = true;
      return report;
    }
    if (report.iterations >= params_.max_iterations) return report;
    // eqs. (48-50): dg/dlambda = dg/dY dY/dlambda = dg/dY W
    dg_dlambda_.noalias() = dg_dy_ * w;
    lu_.compute(dg_dlambda_);
    d_lambda_ = lu_.solve(g_);
    lambda -= d_lambda_;
    report.last_increment = d_lambda_.lpNorm<Eigen::Infinity>();
    ++report.iterations;
  }
}

}  // namespace rig::model::solver
