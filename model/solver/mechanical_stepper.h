#pragma once
/// @file
/// Eq. (8) for one mechanical block (subsystem or framework):
///   M_VI = M - h dq/dz - h^2 dq/dy K^-1                       (modified mass matrix)
///   z(k+1) = z(k) + h M_VI^-1 q(y(k) + h K^-1 z(k), z(k), ...)
///   y(k+1) = y(k) + h K^-1 z(k+1)
/// with the block's dry friction (dry_friction.h) stick-predicted: z(k+1) also gets
/// h M_VI^-1 J^T lambda, lambda the friction forces that stop or oppose the contacts' end speeds.
/// M and K^-1 are frozen at y(k); q and its Jacobians are taken at the predicted coordinates
/// (or at y(k), see ForceEvaluation).

#include <array>
#include <type_traits>

#include <Eigen/Core>

#include "model/solver/couplable_system.h"
#include "model/solver/dense_factorization.h"
#include "model/solver/finite_difference.h"
#include "model/solver/kinematics_product.h"
#include "model/solver/mechanical_block.h"
#include "model/solver/stage.h"

namespace rig::model::solver {

/// Advances one mechanical block; as a CouplableSystem it exposes the two phases of the step for
/// constraint coupling (eqs. 45-46). Factorization: DenseFactorization<N> (default) or, for
/// N = Eigen::Dynamic, ArrowheadFactorization (zero blocks of eqs. 30-31). Workspaces are sized
/// in the constructor; advance(), begin_step() and finish_step() never allocate.
template <int N, typename Factorization = DenseFactorization<N>>
class MechanicalStepper final : public Stage, public CouplableSystem {
 public:
  using Vector = typename MechanicalBlock<N>::Vector;
  using Matrix = typename MechanicalBlock<N>::Matrix;

  /// Dense factorization (or any factorization constructible from the size).
  explicit MechanicalStepper(
      MechanicalBlock<N>& block, JacobianMode mode = JacobianMode::kAnalyticOrFiniteDifference,
      ForceEvaluation evaluation = ForceEvaluation::kPredictedCoordinates) requires
      std::is_constructible_v<Factorization, Eigen::Index>
      : MechanicalStepper(block, block.size(), mode, evaluation) {}

  /// With the factorization built from init, e.g. ArrowheadFactorization from its
  /// ArrowheadPartition (the zero blocks of eqs. 30-31).
  template <typename FactorizationInit>
  requires std::is_constructible_v<Factorization, const FactorizationInit&> MechanicalStepper(
      MechanicalBlock<N>& block, const FactorizationInit& init,
      JacobianMode mode = JacobianMode::kAnalyticOrFiniteDifference,
      ForceEvaluation evaluation = ForceEvaluation::kPredictedCoordinates)
      : block_(block),
        mode_(mode),
        evaluation_(evaluation),
        n_(block.size()),
        k_inv_(n_, n_),
        m_(n_, n_),
        dq_dy_(n_, n_),
        dq_dz_(n_, n_),
        m_vi_(n_, n_),
        y_pred_(n_),
        q_(n_),
        z_u_(n_),
        work_y_(n_),
        work_z_(n_),
        q1_(n_),
        q2_(n_),
        leading_rhs_(n_),
        leading_sol_(n_),
        minv_jt_(n_, FrictionSet<N>::kMaxContacts),
        friction_(n_),
        factorization_(init) {
    minv_jt_.setZero();
    k_inv_.setIdentity();
    m_.setZero();
    dq_dy_.setZero();
    dq_dz_.setZero();
    m_vi_.setZero();
    y_pred_.setZero();
    q_.setZero();
    z_u_.setZero();
    work_y_.setZero();
    work_z_.setZero();
    q1_.setZero();
    q2_.setZero();
    leading_rhs_.setZero();
    leading_sol_.setZero();
  }

  // ---- Stage ----
  void advance(double h) noexcept override {
    begin_step(h);
    finish_step(h);
  }

  // ---- CouplableSystem ----
  [[nodiscard]] Eigen::Index coordinate_size() const noexcept override { return n_; }

  void begin_step(double h) noexcept override {
    const Vector& y = block_.coordinates();
    const Vector& z = block_.speeds();
    block_.kinematics_inverse(y, k_inv_);
    block_.mass_matrix(y, m_);
    // eq. (6): q at the predicted coordinates y(k) + h K^-1 z(k)
    y_pred_ = y;
    if (evaluation_ == ForceEvaluation::kPredictedCoordinates) add_h_k_inv_z(h, z, y_pred_);
    const bool analytic = mode_ == JacobianMode::kAnalyticOrFiniteDifference &&
                          block_.force_jacobians(y_pred_, z, dq_dy_, dq_dz_);
    if (mode_ == JacobianMode::kNone || analytic) {
      block_.applied_forces(y_pred_, z, q_);  // kNone: explicit forces, dq/dy, dq/dz stay zero
    } else {
      finite_difference_force_jacobians<N>(block_, y_pred_, z, dq_dy_, dq_dz_, work_y_, work_z_, q_,
                                           q1_);
    }
    // eq. (8): modified mass matrix M_VI = M - h dq/dz - h^2 dq/dy K^-1
    m_vi_ = m_;
    m_vi_.noalias() -= h * dq_dz_;
    const Eigen::Index blocks3 = block_.kinematics_block3_size();
    if (blocks3 >= 0) {
      subtract_dq_dy_k_inv(blocks3, -(h * h), dq_dy_, k_inv_, m_vi_);
    } else {
      m_vi_.noalias() -= (h * h) * dq_dy_ * k_inv_;
    }
    factorization_.compute(m_vi_);
    factorization_.solve(q_, z_u_);
    resolve_friction(h);
  }

  [[nodiscard]] ConstVectorRef coordinates() const noexcept override {
    return block_.coordinates();
  }
  [[nodiscard]] ConstVectorRef speeds() const noexcept override { return block_.speeds(); }
  [[nodiscard]] ConstMatrixRef kinematics_inverse() const noexcept override { return k_inv_; }
  [[nodiscard]] ConstVectorRef unconstrained_rate() const noexcept override { return z_u_; }

  void solve_mass(ConstMatrixRef b, MatrixRef x) const noexcept override {
    factorization_.solve(b, x);
  }

  void solve_mass_leading(ConstMatrixRef b, MatrixRef x) const noexcept override {
    if constexpr (requires(const Factorization& f, ConstMatrixRef& rhs, MatrixRef& dst) {
                    f.partition();
                    f.body_head_size();
                    f.solve_body(rhs, dst);
                  }) {
      if (b.rows() == factorization_.partition().body_size ||
          b.rows() <= factorization_.body_head_size()) {
        factorization_.solve_body(b, x);  // S^-1 b: the leaves' (and a tail's) rows are zero
        return;
      }
    }
    const Eigen::Index r = b.rows();
    for (Eigen::Index c = 0; c < b.cols(); ++c) {
      leading_rhs_.setZero();
      leading_rhs_.head(r) = b.col(c);
      factorization_.solve(leading_rhs_, leading_sol_);
      x.col(c) = leading_sol_.head(r);
    }
  }

  void finish_step(double h, ConstVectorRef extra_rate) noexcept override {
    Vector& z = block_.speeds();
    z += h * (z_u_ + extra_rate);
    hold_stuck(z);  // a constraint's rate does not unstick (the friction saw only the block)
    add_h_k_inv_z(h, z, block_.coordinates());  // eq. (8): y(k+1) = y(k) + h K^-1 z(k+1)
  }
  /// finish_step without constraint forces.
  void finish_step(double h) noexcept {
    Vector& z = block_.speeds();
    z += h * z_u_;
    hold_stuck(z);
    add_h_k_inv_z(h, z, block_.coordinates());
  }

  // ---- inspection (valid after begin_step) ----
  [[nodiscard]] const Matrix& modified_mass_matrix() const noexcept { return m_vi_; }
  [[nodiscard]] const Matrix& force_jacobian_y() const noexcept { return dq_dy_; }
  [[nodiscard]] const Matrix& force_jacobian_z() const noexcept { return dq_dz_; }
  [[nodiscard]] const Vector& applied_forces() const noexcept { return q_; }
  [[nodiscard]] const Vector& predicted_coordinates() const noexcept { return y_pred_; }
  /// The block's friction contacts of this step and their forces and states.
  [[nodiscard]] const FrictionSet<N>& friction_contacts() const noexcept { return friction_; }
  [[nodiscard]] const FrictionSolution& friction_solution() const noexcept {
    return friction_solution_;
  }

 private:
  static constexpr int kMaxContacts = FrictionSet<N>::kMaxContacts;

  /// The friction forces of the step (dry_friction.h): W = J M_VI^-1 J^T and the free end
  /// speeds b = J (z(k) + h z_u); z_u += M_VI^-1 J^T lambda.
  void resolve_friction(double h) noexcept {
    friction_.clear();
    block_.dry_friction(block_.coordinates(), block_.speeds(), friction_);
    stuck_count_ = 0;
    friction_solution_ = FrictionSolution{};
    const int m = friction_.size();
    if (m == 0) return;
    const auto& j = friction_.directions();
    for (int i = 0; i < m; ++i) {
      work_z_ = j.col(i);
      factorization_.solve(work_z_, work_y_);
      minv_jt_.col(i) = work_y_;
    }
    work_z_ = block_.speeds() + h * z_u_;
    std::array<std::array<double, kMaxContacts>, kMaxContacts> w{};
    std::array<double, kMaxContacts> b{}, c{};
    for (int i = 0; i < m; ++i) {
      b[i] = j.col(i).dot(work_z_);
      c[i] = friction_.capacity(i);
      for (int k = 0; k < m; ++k) w[i][k] = j.col(i).dot(minv_jt_.col(k));
    }
    friction_solution_ = solve_friction(w, b, c, m, h);
    for (int i = 0; i < m; ++i) {
      z_u_.noalias() += friction_solution_.force[i] * minv_jt_.col(i);
      // a stuck coordinate's speed is exactly 0 (not a rounding residue): it holds its position
      if (friction_solution_.exact && friction_solution_.state[i] == FrictionState::kStick &&
          friction_.axis(i) >= 0)
        stuck_[stuck_count_++] = friction_.axis(i);
    }
  }
  /// y += h K^-1 z; K^-1's structure used where the block declares it (kinematics_product.h).
  void add_h_k_inv_z(double h, const Vector& z, Vector& y) const noexcept {
    if constexpr (N == Eigen::Dynamic) {
      const Eigen::Index blocks3 = block_.kinematics_block3_size();
      if (blocks3 >= 0) {
        add_k_inv_times(blocks3, h, k_inv_, z, y);
        return;
      }
    }
    y.noalias() += h * k_inv_ * z;
  }
  void hold_stuck(Vector& z) const noexcept {
    for (int i = 0; i < stuck_count_; ++i) z(stuck_[i]) = 0.0;
  }

  MechanicalBlock<N>& block_;
  JacobianMode mode_ = JacobianMode::kAnalyticOrFiniteDifference;
  ForceEvaluation evaluation_ = ForceEvaluation::kPredictedCoordinates;
  Eigen::Index n_ = 0;
  Matrix k_inv_, m_, dq_dy_, dq_dz_, m_vi_;
  Vector y_pred_, q_, z_u_, work_y_, work_z_, q1_, q2_;
  mutable Vector leading_rhs_, leading_sol_;        ///< solve_mass_leading without a body solve
  Eigen::Matrix<double, N, kMaxContacts> minv_jt_;  ///< M_VI^-1 J^T of the friction contacts
  FrictionSet<N> friction_;
  FrictionSolution friction_solution_;
  std::array<Eigen::Index, kMaxContacts> stuck_{};
  int stuck_count_ = 0;
  Factorization factorization_;
};

}  // namespace rig::model::solver
