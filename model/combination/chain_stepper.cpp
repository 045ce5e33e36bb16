#include "model/combination/chain_stepper.h"

#include <stdexcept>

namespace rig::model::combination {

ChainStepper::ChainStepper(std::vector<solver::CouplableSystem*> units,
                           const ChainConstraint& constraint, solver::NewtonParams params,
                           BeginStepRunner* parallel)
    : units_(std::move(units)),
      constraint_(constraint),
      params_(params),
      parallel_(parallel),
      m_(constraint.size()) {
  if (m_ > kMaxRows || static_cast<int>(units_.size()) != constraint.joint_count() + 1)
    throw std::invalid_argument("combination: too many joints or units for the chain stepper");
  lambda_ = RowVector::Zero(m_);
  g_ = RowVector::Zero(m_);
  d_lambda_ = RowVector::Zero(m_);
  newton_matrix_ = RowMatrix::Zero(m_, m_);
  lu_ = Eigen::PartialPivLU<RowMatrix>(m_);
  for (const solver::CouplableSystem* u : units_) {
    b_.push_back(ChassisMatrix::Zero(6, m_));
    mu_.push_back(ChassisMatrix::Zero(6, m_));
    rhs_.push_back(Eigen::VectorXd::Zero(u->coordinate_size()));  // rows 6.. stay zero
    dz_.push_back(Eigen::VectorXd::Zero(u->coordinate_size()));
    y_u_.push_back(Vector6::Zero());
    y_.push_back(Vector6::Zero());
    w_.push_back(ChassisMatrix::Zero(6, m_));
  }
}

void ChainStepper::evaluate() noexcept {
  for (std::size_t j = 0; j < units_.size(); ++j) {
    y_[j] = y_u_[j];
    y_[j].noalias() += w_[j] * lambda_;  // eq. (45): linear in lambda
  }
  for (int i = 0; i < constraint_.joint_count(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Joint& joint = constraint_.joint(i);
    const int rows = joint.size();
    const Eigen::Index r = constraint_.row(i);
    JointEvaluation& e = cache_[k];
    joint.evaluate(y_[k], y_[k + 1], e);
    g_.segment(r, rows) = e.g.head(rows);
  }
}

void ChainStepper::assemble_newton_matrix() noexcept {
  // eqs. (49-50): dg/dlambda = sum_j dg/dy_j W_j, dg/dy from the last evaluate()
  for (int i = 0; i < constraint_.joint_count(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    const int rows = constraint_.joint(i).size();
    const Eigen::Index r = constraint_.row(i);
    const JointEvaluation& e = cache_[k];
    newton_matrix_.middleRows(r, rows).noalias() = e.dg_dya.topRows(rows).lazyProduct(w_[k]);
    newton_matrix_.middleRows(r, rows).noalias() += e.dg_dyb.topRows(rows).lazyProduct(w_[k + 1]);
  }
}

solver::NewtonReport ChainStepper::step(double h) noexcept {
  // eq. (46): every unit alone up to z^u and its M_VI factorization
  if (parallel_ != nullptr) {
    parallel_->start(h);
    units_[0]->begin_step(h);
    parallel_->wait();
  } else {
    for (solver::CouplableSystem* u : units_) u->begin_step(h);
  }
  // (lazyProduct: these products are tiny, Eigen's GEMM kernel would cost more than the work)
  // J_j = dg/dy_j K_j^-1 at y(k) (chassis block of K^-1) -> b_j = J_j^T (chassis rows)
  for (auto& b : b_) b.setZero();
  for (int i = 0; i < constraint_.joint_count(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Joint& joint = constraint_.joint(i);
    const int rows = joint.size();
    const Eigen::Index r = constraint_.row(i);
    JointEvaluation& e = cache_[k];
    if (!cache_valid_) {
      joint.evaluate(units_[k]->coordinates().head<6>(), units_[k + 1]->coordinates().head<6>(), e);
    }
    // copies: the Ref returned by kinematics_inverse() is a temporary
    const Matrix6 ka = units_[k]->kinematics_inverse().topLeftCorner<6, 6>();
    const Matrix6 kb = units_[k + 1]->kinematics_inverse().topLeftCorner<6, 6>();
    b_[k].middleCols(r, rows).noalias() =
        ka.transpose().lazyProduct(e.dg_dya.topRows(rows).transpose());
    b_[k + 1].middleCols(r, rows).noalias() =
        kb.transpose().lazyProduct(e.dg_dyb.topRows(rows).transpose());
  }
  for (std::size_t j = 0; j < units_.size(); ++j) {
    const solver::CouplableSystem& u = *units_[j];
    // eq. (46), chassis rows only: mu_j = [M_VIj^-1 [J_j^T; 0]]_chassis = S_j^-1 J_j^T
    u.solve_mass_leading(b_[j], mu_[j]);
    const Matrix6 k_inv = u.kinematics_inverse().topLeftCorner<6, 6>();
    Vector6 z = u.speeds().head<6>();
    z.noalias() += h * u.unconstrained_rate().head<6>();
    y_u_[j] = u.coordinates().head<6>();
    y_u_[j].noalias() += h * k_inv * z;
    w_[j].noalias() = ((h * h) * k_inv).lazyProduct(mu_[j]);
  }
  // eqs. (47-49): Newton on the stacked lambda, warm-started (see constraint_coupling.h for the
  // criterion: |g| and the relative lambda increment)
  solver::NewtonReport report;
  for (;;) {
    evaluate();
    report.residual = g_.lpNorm<Eigen::Infinity>();
    if (solver::newton_converged(params_, report, lambda_)) {
      report.converged = true;
      break;
    }
    if (report.iterations >= params_.max_iterations) break;
    assemble_newton_matrix();  // only when iterating: the converged evaluation does not need it
    lu_.compute(newton_matrix_);
    d_lambda_.noalias() = lu_.solve(g_);
    lambda_ -= d_lambda_;
    report.last_increment = d_lambda_.lpNorm<Eigen::Infinity>();
    ++report.iterations;
  }
  report_ = report;
  cache_valid_ = true;  // the last evaluate() was at the final lambda, i.e. at y(k+1)
  // eq. (45): z(k+1) = z(k) + h (z^u + M_VI^-1 [J^T lambda; 0]), one full solve per unit
  for (std::size_t j = 0; j < units_.size(); ++j) {
    rhs_[j].head<6>().noalias() = b_[j] * lambda_;
    units_[j]->solve_mass(rhs_[j], dz_[j]);
    units_[j]->finish_step(h, dz_[j]);
  }
  return report_;
}

}  // namespace rig::model::combination
