#pragma once
/// @file
/// A system that can be coupled to others by constraints (eqs. 45-50): it computes its
/// unconstrained update z^u and lets the coupling ask for mu = M_VI^-1 (dg/dy K^-1)^T, all
/// independently of the other systems (so they could run in parallel).

#include <Eigen/Core>

namespace rig::model::solver {

/// One step of a couplable system is split in two phases around the Newton loop on lambda:
///   begin_step(h): everything up to the factorization of M_VI and z^u = M_VI^-1 q (eq. 46);
///   finish_step(h, dz): z(k+1) = z(k) + h (z^u + dz), y(k+1) = y(k) + h K^-1 z(k+1) (eq. 45),
///   where dz = mu lambda is the response to the constraint forces.
/// A system that is not coupled calls finish_step with dz = 0. Nothing allocates.
class CouplableSystem {
 public:
  using ConstVectorRef = Eigen::Ref<const Eigen::VectorXd>;
  using ConstMatrixRef = Eigen::Ref<const Eigen::MatrixXd>;
  using MatrixRef = Eigen::Ref<Eigen::MatrixXd>;

  CouplableSystem() = default;
  CouplableSystem(const CouplableSystem&) = delete;
  CouplableSystem& operator=(const CouplableSystem&) = delete;
  virtual ~CouplableSystem() = default;

  /// Number of generalized coordinates (= speeds) of the framework.
  [[nodiscard]] virtual Eigen::Index coordinate_size() const noexcept = 0;
  /// Phase 1, see the class comment.
  virtual void begin_step(double h) noexcept = 0;
  /// y(k) (unchanged by begin_step).
  [[nodiscard]] virtual ConstVectorRef coordinates() const noexcept = 0;
  /// z(k) (unchanged by begin_step).
  [[nodiscard]] virtual ConstVectorRef speeds() const noexcept = 0;
  /// K^-1(y(k)) as used in this step; valid after begin_step.
  [[nodiscard]] virtual ConstMatrixRef kinematics_inverse() const noexcept = 0;
  /// z^u = M_VI^-1 q (eq. 46); valid after begin_step.
  [[nodiscard]] virtual ConstVectorRef unconstrained_rate() const noexcept = 0;
  /// x = M_VI^-1 b with this step's factorization (e.g. mu of eq. 46 for b = (dg/dy K^-1)^T);
  /// valid after begin_step. b and x: coordinate_size() rows, any number of columns.
  virtual void solve_mass(ConstMatrixRef b, MatrixRef x) const noexcept = 0;
  /// x = the first r = b.rows() rows of M_VI^-1 [b; 0] (r <= coordinate_size()), for a
  /// right-hand side that is zero below row r, e.g. constraint forces on the chassis coordinates
  /// only. A framework with an arrowhead M_VI and r = its body size answers it with the body's
  /// Schur complement alone (ArrowheadFactorization::solve_body); otherwise it is the full solve
  /// restricted to those rows. Valid after begin_step. b and x: r rows, any number of columns.
  virtual void solve_mass_leading(ConstMatrixRef b, MatrixRef x) const noexcept = 0;
  /// Phase 2, see the class comment. extra_rate: coordinate_size() entries.
  virtual void finish_step(double h, ConstVectorRef extra_rate) noexcept = 0;
};

}  // namespace rig::model::solver
