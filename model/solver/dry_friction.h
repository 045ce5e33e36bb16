#pragma once
/// @file
/// Stick-predicted dry friction in the implicit step (as the brakes in WheelSpinStage): a block
/// declares friction contacts, each a direction j in its speeds (relative speed v = j^T z) with a
/// capacity c >= 0; the stepper finds the friction forces lambda (generalized force j lambda) of
/// the step so that, with z(k+1) = z(k) + h M_VI^-1 (q + J^T lambda), every contact either
/// sticks (v(k+1) = 0 exactly, |lambda| <= c) or slides (lambda = -c sign v(k+1)). No slope in
/// M_VI: a stuck coordinate holds its position; a sliding one sees exactly its capacity.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <Eigen/Core>

namespace rig::model::solver {

/// The contacts a block declares for one step (MechanicalBlock::dry_friction). Sized once for
/// the block's speeds (no allocation per step); at most kMaxContacts contacts.
template <int N>
class FrictionSet {
 public:
  static constexpr int kMaxContacts = 4;
  using Vector = Eigen::Matrix<double, N, 1>;
  using Directions = Eigen::Matrix<double, N, kMaxContacts>;

  explicit FrictionSet(Eigen::Index n) : directions_(Directions::Zero(n, kMaxContacts)) {}

  void clear() noexcept { count_ = 0; }
  /// Friction on speed `index` alone (a bearing, the rack's guide). Capacity 0 adds nothing.
  /// Returns false when full.
  bool add_on_coordinate(Eigen::Index index, double capacity) noexcept {
    if (capacity <= 0.0) return true;
    if (count_ == kMaxContacts) return false;
    directions_.col(count_).setZero();
    directions_(index, count_) = 1.0;
    axis_[count_] = index;
    capacity_[count_++] = capacity;
    return true;
  }
  /// Friction on the relative speed direction^T z (e.g. between two bodies: +1 and -1).
  bool add_on_direction(const Vector& direction, double capacity) noexcept {
    if (capacity <= 0.0) return true;
    if (count_ == kMaxContacts) return false;
    directions_.col(count_) = direction;
    axis_[count_] = -1;
    capacity_[count_++] = capacity;
    return true;
  }

  [[nodiscard]] int size() const noexcept { return count_; }
  [[nodiscard]] const Directions& directions() const noexcept { return directions_; }
  [[nodiscard]] double capacity(int i) const noexcept { return capacity_[i]; }
  /// The speed index of a contact on one coordinate, -1 for a general direction.
  [[nodiscard]] Eigen::Index axis(int i) const noexcept { return axis_[i]; }

 private:
  Directions directions_;
  std::array<double, kMaxContacts> capacity_{};
  std::array<Eigen::Index, kMaxContacts> axis_{};
  int count_ = 0;
};

/// A contact's state after the step.
enum class FrictionState : std::uint8_t { kStick, kSlidePositive, kSlideNegative };

/// The small box-constrained problem of the step in the contacts' speeds:
///   v = b + h W lambda,  W = J M_VI^-1 J^T,  b = J (z(k) + h z_u),
/// each contact: v_i = 0 with |lambda_i| <= c_i (stick) or lambda_i = -c_i sign(v_i) (slide).
/// Solved exactly by enumerating the 3^m stick / slide-up / slide-down sets (m <= 4: <= 81 small
/// eliminations), first consistent set in a fixed order (stick first); for a W with positive
/// definite symmetric part the solution is unique, so the order only settles ties at the
/// boundary. If no set is consistent (W far from that), a projected Gauss-Seidel with a fixed
/// 200 sweeps (deterministic; residual not guaranteed below 1e-9 c). No allocation.
struct FrictionSolution {
  static constexpr int kMax = 4;
  std::array<double, kMax> force{};  ///< lambda_i (generalized force along direction i)
  std::array<FrictionState, kMax> state{};
  bool exact = true;  ///< false: the Gauss-Seidel fallback
};

namespace detail {

/// Solves a x = r for m <= 4 by Gaussian elimination with partial pivoting; false if singular.
inline bool solve_small(std::array<std::array<double, 4>, 4> a, std::array<double, 4> r, int m,
                        std::array<double, 4>& x) noexcept {
  for (int k = 0; k < m; ++k) {
    int p = k;
    for (int i = k + 1; i < m; ++i)
      if (std::abs(a[i][k]) > std::abs(a[p][k])) p = i;
    if (!(std::abs(a[p][k]) > 0.0)) return false;
    std::swap(a[k], a[p]);
    std::swap(r[k], r[p]);
    for (int i = k + 1; i < m; ++i) {
      const double f = a[i][k] / a[k][k];
      for (int j = k; j < m; ++j) a[i][j] -= f * a[k][j];
      r[i] -= f * r[k];
    }
  }
  for (int k = m - 1; k >= 0; --k) {
    double s = r[k];
    for (int j = k + 1; j < m; ++j) s -= a[k][j] * x[j];
    x[k] = s / a[k][k];
  }
  return true;
}

}  // namespace detail

namespace detail {

using Square4 = std::array<std::array<double, 4>, 4>;
using Column4 = std::array<double, 4>;

/// One stick / slide set (3^m code, contact i's digit: 0 stick, 1 slide up, 2 slide down): the
/// sliding forces are their capacities, the stuck ones make their speeds zero. True and the
/// forces if the set is consistent (stuck within capacity, sliding in its direction).
inline bool try_friction_set(const Square4& w, const Column4& b, const Column4& c, int m, double h,
                             int code, Column4& lambda, std::array<FrictionState, 4>& st) noexcept {
  std::array<int, 4> stuck{};
  int ns = 0;
  for (int i = 0; i < m; ++i, code /= 3) {
    st[i] = static_cast<FrictionState>(code % 3);
    lambda[i] = st[i] == FrictionState::kSlidePositive   ? -c[i]
                : st[i] == FrictionState::kSlideNegative ? c[i]
                                                         : 0.0;
    if (st[i] == FrictionState::kStick) stuck[ns++] = i;
  }
  if (ns > 0) {  // W_SS lambda_S = -b_S / h - W_SL lambda_L
    Square4 a{};
    Column4 r{}, x{};
    for (int p = 0; p < ns; ++p) {
      const int i = stuck[p];
      r[p] = -b[i] / h;
      for (int j = 0; j < m; ++j)
        if (st[j] != FrictionState::kStick) r[p] -= w[i][j] * lambda[j];
      for (int q = 0; q < ns; ++q) a[p][q] = w[i][stuck[q]];
    }
    if (!solve_small(a, r, ns, x)) return false;
    for (int p = 0; p < ns; ++p) lambda[stuck[p]] = x[p];
  }
  constexpr double kTol = 1e-12;
  for (int i = 0; i < m; ++i) {
    double v = b[i];
    for (int j = 0; j < m; ++j) v += h * w[i][j] * lambda[j];
    const double scale = std::abs(b[i]) + kTol;
    if (st[i] == FrictionState::kStick && !(std::abs(lambda[i]) <= c[i] * (1 + kTol))) return false;
    if (st[i] == FrictionState::kSlidePositive && v < -kTol * scale) return false;
    if (st[i] == FrictionState::kSlideNegative && v > kTol * scale) return false;
  }
  return true;
}

/// Fallback: projected Gauss-Seidel on v = b + h W lambda = 0, lambda in [-c, c], 200 sweeps.
inline FrictionSolution friction_gauss_seidel(const Square4& w, const Column4& b, const Column4& c,
                                              int m, double h) noexcept {
  FrictionSolution s;
  s.exact = false;
  Column4 lambda{};
  for (int sweep = 0; sweep < 200; ++sweep) {
    for (int i = 0; i < m; ++i) {
      double v = b[i];
      for (int j = 0; j < m; ++j) v += h * w[i][j] * lambda[j];
      if (w[i][i] > 0.0) lambda[i] = std::clamp(lambda[i] - v / (h * w[i][i]), -c[i], c[i]);
    }
  }
  for (int i = 0; i < m; ++i) {
    s.force[i] = lambda[i];
    s.state[i] = lambda[i] <= -c[i]  ? FrictionState::kSlidePositive
                 : lambda[i] >= c[i] ? FrictionState::kSlideNegative
                                     : FrictionState::kStick;
  }
  return s;
}

}  // namespace detail

/// w: W (m x m, row-major in the first m rows/cols), b: free end speeds, c: capacities.
inline FrictionSolution solve_friction(const detail::Square4& w, const detail::Column4& b,
                                       const detail::Column4& c, int m, double h) noexcept {
  FrictionSolution s;
  int cases = 1;
  for (int i = 0; i < m; ++i) cases *= 3;
  for (int code = 0; code < cases; ++code)
    if (detail::try_friction_set(w, b, c, m, h, code, s.force, s.state)) return s;
  return detail::friction_gauss_seidel(w, b, c, m, h);
}

}  // namespace rig::model::solver
