#pragma once
/// @file
/// The force-coupling baseline (eqs. 32-38): the same joints as stiff spring-dampers
///   F = F_0 - (C g + D g'),  g' = J z,  J = dg/dY K^-1  (force on the leading unit, road frame),
/// F_0 the static hitch load (the spring is preloaded, so that the combination starts in
/// equilibrium as the DAE does instead of ringing at the spring's frequency),
/// integrated by the modified implicit Euler with ONE implicit matrix for the whole combination:
///   [blockdiag(M_VI_j) + J^T (h D + h^2 C) J] dz = q + J^T F(Y_pred, Z(k)),
///   z(k+1) = z(k) + h dz,  y(k+1) = y(k) + h K^-1 z(k+1).
/// The spring's Jacobian couples the units, so a dense LU of the stacked size is needed every
/// step (the units' own M_VI are still assembled by their begin_step; their arrowhead
/// factorizations are then unused). For comparing speed and accuracy with the DAE approach.

#include <memory>
#include <vector>

#include <Eigen/LU>

#include "model/combination/combination_shell.h"

namespace rig::model::combination {

class ForceCoupledCombination final : public CombinationShell {
 public:
  ForceCoupledCombination(const CombinationParams& params, double step_size_s);

  /// Spring-damper force of joint i on its leading unit at the end of the last step [N].
  [[nodiscard]] Vec3 joint_force_n(int i) const noexcept override {
    return force_.segment<3>(constraint_->row(i));
  }

 private:
  bool couple(double h) noexcept override;
  void reset_coupling() noexcept override;

  Eigen::Index n_ = 0, m_ = 0;
  Eigen::VectorXd stiffness_, damping_;  // C, D (diagonal, per constraint row)
  Eigen::VectorXd preload_;              // F_0
  Eigen::VectorXd y_, z_, y_pred_, g_, g_pred_, q_, dz_, force_, work_m_, extra_;
  Eigen::MatrixXd k_inv_, dg_dy_, dg_pred_, jac_, m_big_, jw_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace rig::model::combination
