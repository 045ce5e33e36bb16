#include "model/solver/coupled_stepper.h"

#include <utility>

namespace rig::model::solver {

CoupledStepper::CoupledStepper(std::vector<CouplableSystem*> systems,
                               const ConstraintFunction& constraint, NewtonParams params)
    : systems_(std::move(systems)),
      constraint_(constraint),
      total_([this] {
        Eigen::Index total = 0;
        for (const CouplableSystem* s : systems_) total += s->coordinate_size();
        return total;
      }()),
      n_lambda_(constraint.size()),
      newton_(constraint, total_, params),
      y_(total_),
      y_u_(total_),
      g_(n_lambda_),
      lambda_(Eigen::VectorXd::Zero(n_lambda_)),
      dz_(total_),
      dg_dy_(n_lambda_, total_),
      w_(total_, n_lambda_),
      b_(total_, n_lambda_),
      mu_(total_, n_lambda_) {
  Eigen::Index offset = 0;
  for (const CouplableSystem* s : systems_) {
    offsets_.push_back(offset);
    offset += s->coordinate_size();
  }
}

void CoupledStepper::stacked_coordinates(Eigen::Ref<Eigen::VectorXd> y) const noexcept {
  for (std::size_t j = 0; j < systems_.size(); ++j) {
    y.segment(offsets_[j], systems_[j]->coordinate_size()) = systems_[j]->coordinates();
  }
}

NewtonReport CoupledStepper::step(double h) noexcept {
  // eq. (46): each system alone - force elements, subsystems, M_VI, z^u
  for (CouplableSystem* s : systems_) s->begin_step(h);
  stacked_coordinates(y_);
  constraint_.evaluate(y_, g_, dg_dy_);  // dg/dY at y(k), for mu
  for (std::size_t j = 0; j < systems_.size(); ++j) {
    CouplableSystem& s = *systems_[j];
    const Eigen::Index o = offsets_[j];
    const Eigen::Index n = s.coordinate_size();
    const auto k_inv = s.kinematics_inverse();
    // eq. (46): mu_j = M_VIj^-1 (dg/dy_j K_j^-1)^T
    b_.middleRows(o, n).noalias() = k_inv.transpose() * dg_dy_.middleCols(o, n).transpose();
    s.solve_mass(b_.middleRows(o, n), mu_.middleRows(o, n));
    // eq. (45) at lambda = 0 and its derivative (eq. 50): Y_u and W = h^2 K^-1 mu
    auto y_u = y_u_.segment(o, n);
    auto dz = dz_.segment(o, n);
    dz = s.speeds();
    dz += h * s.unconstrained_rate();
    y_u = s.coordinates();
    y_u.noalias() += h * k_inv * dz;
    w_.middleRows(o, n).noalias() = (h * h) * k_inv * mu_.middleRows(o, n);
  }
  report_ = newton_.solve(y_u_, w_, lambda_);  // eqs. (47-50), warm-started
  dz_.noalias() = mu_ * lambda_;
  for (std::size_t j = 0; j < systems_.size(); ++j) {
    systems_[j]->finish_step(h, dz_.segment(offsets_[j], systems_[j]->coordinate_size()));
  }
  return report_;
}

}  // namespace rig::model::solver
