#pragma once
/// @file
/// One planar pendulum as a 1-DOF framework block: y = phi, z = v = a phi' (so K = a),
/// M = m, q = -m g sin(phi) (sec. 3.4).

#include "model/solver/mechanical_block.h"

namespace rig::model::paper {

class Pendulum final : public solver::MechanicalBlock<1> {
 public:
  Pendulum(double mass_kg, double length_m, double gravity_mps2, double phi0_rad);

  [[nodiscard]] Eigen::Index size() const noexcept override { return 1; }
  [[nodiscard]] Vector& coordinates() noexcept override { return y_; }
  [[nodiscard]] Vector& speeds() noexcept override { return z_; }
  void kinematics_inverse(const Vector& y, Matrix& k_inv) const noexcept override;
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;

  [[nodiscard]] double angle_rad() const noexcept { return y_(0); }
  [[nodiscard]] double speed_mps() const noexcept { return z_(0); }

 private:
  double mass_kg_, length_m_, gravity_mps2_;
  Vector y_, z_;
};

}  // namespace rig::model::paper
