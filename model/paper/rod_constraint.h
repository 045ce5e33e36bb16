#pragma once
/// @file
/// The rigid rod of sec. 3.4 as a constraint g = l(phi1, phi2) - s = 0 over Y = [phi1, phi2].

#include "model/paper/coupled_pendulums_params.h"
#include "model/solver/constraint_coupling.h"

namespace rig::model::paper {

class RodConstraint final : public solver::ConstraintFunction {
 public:
  RodConstraint(const CoupledPendulumsParams& params, double rod_length_m)
      : params_(params), rod_length_m_(rod_length_m) {}

  [[nodiscard]] Eigen::Index size() const noexcept override { return 1; }
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> dg_dy) const noexcept override;

 private:
  CoupledPendulumsParams params_;
  double rod_length_m_;
};

}  // namespace rig::model::paper
