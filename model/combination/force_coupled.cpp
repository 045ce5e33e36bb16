#include "model/combination/force_coupled.h"

#include <stdexcept>

namespace rig::model::combination {

ForceCoupledCombination::ForceCoupledCombination(const CombinationParams& params,
                                                 double step_size_s)
    : CombinationShell(params, step_size_s) {
  for (const auto& u : units_) n_ += u->coordinate_size();
  for (const JointParams& j : p_.joints) {
    if (j.kind == JointKind::kTowBar)
      throw std::invalid_argument("force-coupled baseline: the tow bar joint is not implemented");
  }
  m_ = constraint_->size();
  stiffness_ = Eigen::VectorXd::Zero(m_);
  damping_ = Eigen::VectorXd::Zero(m_);
  for (int i = 0; i < constraint_->joint_count(); ++i) {
    const JointParams& j = constraint_->joint(i).params();
    const Eigen::Index r = constraint_->row(i);
    stiffness_.segment<3>(r).setConstant(j.stiffness_npm);
    damping_.segment<3>(r).setConstant(j.damping_nspm);
    if (j.kind == JointKind::kFifthWheel) {
      stiffness_(r + 3) = j.roll_stiffness_nmpr;
      damping_(r + 3) = j.roll_damping_nmspr;
    }
  }
  for (Eigen::VectorXd* v : {&y_, &z_, &y_pred_, &q_, &dz_, &extra_})
    *v = Eigen::VectorXd::Zero(n_);
  for (Eigen::VectorXd* v : {&g_, &g_pred_, &force_, &work_m_, &preload_})
    *v = Eigen::VectorXd::Zero(m_);
  k_inv_ = Eigen::MatrixXd::Zero(n_, n_);
  m_big_ = Eigen::MatrixXd::Zero(n_, n_);
  dg_dy_ = Eigen::MatrixXd::Zero(m_, n_);
  dg_pred_ = Eigen::MatrixXd::Zero(m_, n_);
  jac_ = Eigen::MatrixXd::Zero(m_, n_);
  jw_ = Eigen::MatrixXd::Zero(m_, n_);
  lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(n_);
  reset(0, 0, 0);
}

void ForceCoupledCombination::reset_coupling() noexcept {
  preload_.setZero();
  for (int i = 0; i < constraint_->joint_count(); ++i) {
    preload_(constraint_->row(i) + 2) =
        -units_[static_cast<std::size_t>(i) + 1]->framework().support_load_n();
  }
  force_ = preload_;
}

bool ForceCoupledCombination::couple(double h) noexcept {
  m_big_.setZero();
  k_inv_.setZero();
  for (std::size_t j = 0; j < units_.size(); ++j) {
    vehicle::VehicleModel& u = *units_[j];
    u.begin_step(h);  // eq. (8) up to M_VI and q of each unit
    const Eigen::Index o = constraint_->offset(static_cast<int>(j));
    const Eigen::Index n = u.coordinate_size();
    y_.segment(o, n) = u.coordinates();
    z_.segment(o, n) = u.speeds();
    k_inv_.block(o, o, n, n) = u.kinematics_inverse();
    m_big_.block(o, o, n, n) = u.modified_mass_matrix();
    q_.segment(o, n) = u.applied_forces();
  }
  // J = dg/dY K^-1 at y(k); g at the predicted coordinates (eq. 6)
  constraint_->evaluate(y_, g_, dg_dy_);
  jac_.noalias() = dg_dy_ * k_inv_;
  y_pred_ = y_;
  y_pred_.noalias() += h * k_inv_ * z_;
  constraint_->evaluate(y_pred_, g_pred_, dg_pred_);
  // eqs. (32-38): F = F_0 - (C g + D J z); M_big = blockdiag(M_VI) + J^T (h D + h^2 C) J
  work_m_.noalias() = jac_ * z_;
  force_ = preload_ - (stiffness_.cwiseProduct(g_pred_) + damping_.cwiseProduct(work_m_));
  jw_ = (h * damping_ + (h * h) * stiffness_).asDiagonal() * jac_;
  m_big_.noalias() += jac_.transpose() * jw_;
  q_.noalias() += jac_.transpose() * force_;
  lu_.compute(m_big_);
  dz_ = lu_.solve(q_);
  // the implicit spring force at t + h (linearized): F - (h D + h^2 C) J dz
  force_.noalias() -= jw_ * dz_;
  for (std::size_t j = 0; j < units_.size(); ++j) {
    vehicle::VehicleModel& u = *units_[j];
    const Eigen::Index o = constraint_->offset(static_cast<int>(j));
    const Eigen::Index n = u.coordinate_size();
    extra_.segment(o, n) = dz_.segment(o, n) - u.unconstrained_rate();
    u.finish_step(h, extra_.segment(o, n));  // z(k+1) = z(k) + h dz
  }
  return dz_.allFinite();
}

}  // namespace rig::model::combination
