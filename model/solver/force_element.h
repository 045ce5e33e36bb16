#pragma once
/// @file
/// A dynamic force element (eq. 3): a block with its own states s and a first-order law
/// s' = f(s, y, z). Tires (deflection x_e, y_e), hydro mounts and dampers with internal states are
/// force elements. The element reads the newest coordinates and speeds of the other blocks itself
/// (through references it got at construction); the solver only sees s.

#include <Eigen/Core>

namespace rig::model::solver {

/// Interface of a force element with N states (N may be Eigen::Dynamic). The element owns its
/// state vector; ForceElementStepper advances it by eq. (8), first line. Every method is called
/// in the RT path: no allocation, no exceptions.
template <int N>
class ForceElement {
 public:
  using Vector = Eigen::Matrix<double, N, 1>;
  using Matrix = Eigen::Matrix<double, N, N>;

  ForceElement() = default;
  ForceElement(const ForceElement&) = delete;
  ForceElement& operator=(const ForceElement&) = delete;
  virtual ~ForceElement() = default;

  /// Number of states (N if N is fixed).
  [[nodiscard]] virtual Eigen::Index state_size() const noexcept = 0;
  /// The states s, owned by the element.
  [[nodiscard]] virtual Vector& state() noexcept = 0;
  /// The rate f(s, ...) at the given s and the current states of the other blocks (eq. 3).
  /// Must not change the element: the finite-difference fallback calls it at perturbed s.
  virtual void rate(const Vector& s, Vector& f) const noexcept = 0;
  /// The analytic df/ds at s; returns false if the element has none (then the stepper uses
  /// forward differences of rate()).
  virtual bool rate_jacobian(const Vector& s, Matrix& df_ds) const noexcept {
    (void)s;
    (void)df_ds;
    return false;
  }
  /// Called after the implicit update with the new state, e.g. for the stick-slip limiter of
  /// eq. (26), which may clamp the state. Default: nothing.
  virtual void after_update(Vector& s) noexcept { (void)s; }
};

}  // namespace rig::model::solver
