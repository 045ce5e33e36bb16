#pragma once
/// @file
/// Eq. (8), first line: s(k+1) = s(k) + h [I - h df/ds]^-1 f(s(k), ...), one linear solve.

#include <Eigen/Core>
#include <Eigen/LU>

#include "model/solver/finite_difference.h"
#include "model/solver/fixed_lu.h"
#include "model/solver/force_element.h"
#include "model/solver/stage.h"

namespace rig::model::solver {

/// Advances one force element. Workspaces are sized in the constructor.
template <int N>
class ForceElementStepper final : public Stage {
 public:
  using Vector = typename ForceElement<N>::Vector;
  using Matrix = typename ForceElement<N>::Matrix;

  explicit ForceElementStepper(ForceElement<N>& element,
                               JacobianMode mode = JacobianMode::kAnalyticOrFiniteDifference)
      : element_(element),
        mode_(mode),
        f_(element.state_size()),
        jac_(element.state_size(), element.state_size()),
        a_(element.state_size(), element.state_size()),
        ds_(element.state_size()),
        work_(element.state_size()),
        f1_(element.state_size()),
        lu_(element.state_size()) {
    f_.setZero();
    jac_.setZero();
    a_.setZero();
    ds_.setZero();
    work_.setZero();
    f1_.setZero();
  }

  void advance(double h) noexcept override {
    Vector& s = element_.state();
    const bool analytic =
        mode_ == JacobianMode::kAnalyticOrFiniteDifference && element_.rate_jacobian(s, jac_);
    if (mode_ == JacobianMode::kNone) {
      jac_.setZero();  // explicit Euler for a non-stiff element
      element_.rate(s, f_);
    } else if (!analytic) {
      finite_difference_rate_jacobian<N>(element_, s, jac_, work_, f_, f1_);
    } else {
      element_.rate(s, f_);
    }
    // eq. (5): linearized implicit Euler
    a_.setIdentity();
    a_.noalias() -= h * jac_;
    lu_.compute(a_);
    ds_ = lu_.solve(f_);
    s += h * ds_;
    element_.after_update(s);
  }

  /// The rate f(s(k)) and its Jacobian used in the last step.
  [[nodiscard]] const Vector& last_rate() const noexcept { return f_; }
  [[nodiscard]] const Matrix& last_jacobian() const noexcept { return jac_; }

 private:
  ForceElement<N>& element_;
  JacobianMode mode_;
  Vector f_;
  Matrix jac_, a_;
  Vector ds_, work_, f1_;
  typename PartialPivLuOf<N>::type lu_;
};

}  // namespace rig::model::solver
