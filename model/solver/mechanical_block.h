#pragma once
/// @file
/// A mechanical block: a subsystem (eq. 2) or the framework (eq. 1). Generalized coordinates y,
/// generalized speeds z, kinematic matrix K (K y' = z), mass matrix M and applied forces q with
/// their partial Jacobians dq/dy, dq/dz.

#include <Eigen/Core>

#include "model/solver/dry_friction.h"

namespace rig::model::solver {

/// Interface of a mechanical block with N coordinates and N speeds (N may be Eigen::Dynamic;
/// y and z have the same size, K is square). The block owns y and z; MechanicalStepper advances
/// them by eq. (8). It reads the newest states of the other blocks itself.
///
/// Every method is called in the RT path: no allocation, no exceptions. applied_forces() must
/// not change the block: the finite-difference fallback calls it at perturbed y and z.
template <int N>
class MechanicalBlock {
 public:
  using Vector = Eigen::Matrix<double, N, 1>;
  using Matrix = Eigen::Matrix<double, N, N>;

  MechanicalBlock() = default;
  MechanicalBlock(const MechanicalBlock&) = delete;
  MechanicalBlock& operator=(const MechanicalBlock&) = delete;
  virtual ~MechanicalBlock() = default;

  /// Number of coordinates = number of speeds.
  [[nodiscard]] virtual Eigen::Index size() const noexcept = 0;
  /// Generalized coordinates y.
  [[nodiscard]] virtual Vector& coordinates() noexcept = 0;
  /// Generalized speeds z.
  [[nodiscard]] virtual Vector& speeds() noexcept = 0;
  /// K^-1(y), so that y' = K^-1 z. Default: identity (y' = z). Blocks know K analytically
  /// (e.g. a rotation and the Euler-rate matrix for a chassis; 1/a for a pendulum).
  virtual void kinematics_inverse(const Vector& y, Matrix& k_inv) const noexcept {
    (void)y;
    k_inv.setIdentity(size(), size());
  }
  /// The structure of K^-1, if known: 3 x 3 diagonal blocks over its first
  /// kinematics_block3_size() rows and columns (a multiple of 3), the identity after them (a
  /// chassis' rotation and Euler-rate blocks, then hub travels: eq. 1). -1 (default): dense.
  /// The stepper then forms dq/dy K^-1 without the products with K's zeros.
  [[nodiscard]] virtual Eigen::Index kinematics_block3_size() const noexcept { return -1; }
  /// Mass matrix M(y); frozen at the start of the step.
  virtual void mass_matrix(const Vector& y, Matrix& m) const noexcept = 0;
  /// Generalized applied forces q(y, z, newest states of the other blocks).
  virtual void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept = 0;
  /// Analytic partial Jacobians of q (only the stiff parts are needed, method.md sec. 6); return
  /// false if the block has none (then the stepper uses forward differences of applied_forces).
  virtual bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                               Matrix& dq_dz) const noexcept {
    (void)y;
    (void)z;
    (void)dq_dy;
    (void)dq_dz;
    return false;
  }
  /// The block's dry-friction contacts for this step (dry_friction.h), at y(k), z(k): the
  /// stepper solves them stick-predicted instead of a regularised slope in q. Default: none.
  virtual void dry_friction(const Vector& y, const Vector& z,
                            FrictionSet<N>& contacts) const noexcept {
    (void)y;
    (void)z;
    contacts.clear();
  }
};

}  // namespace rig::model::solver
