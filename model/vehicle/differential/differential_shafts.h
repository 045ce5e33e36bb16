#pragma once
/// @file
/// The half shafts behind a tree of differentials (differential_tree.h) as a force element
/// (eq. 3): per driven wheel a torsionally compliant shaft, T_i = c theta_i + d (w_side_i - w_i),
/// theta_i' = w_side_i - w_i. The gears are massless (as HalfShafts' open differentials), so each
/// differential's relative speed delta_j follows algebraically from its balance
///   (G^T T)_j + c_v,j delta_j = lambda_j,
/// lambda_j the clutch couple of a limited-slip differential (|lambda_j| <= T_L,j / 2); a locked
/// differential (or a clutch that sticks) has delta_j = 0, a constraint. With x = c theta +
/// d (w_c 1 - w) and G~, K~ = d G~^T G~ + C_v the tree without its fixed differentials:
///   delta = K~^-1 (lambda - G~^T x),   T = x + d G~ delta,   dT/dx = I - d G~ K~^-1 G~^T.
/// Linear between stick / slide changes, so its Jacobian is exact: d theta'/d theta = -c S with
/// S = G~ K~^-1 G~^T, and -dT_i/dw_i = d - d^2 S_ii for the wheel spins. The clutches' stick or
/// slide is predicted by the dry-friction solve of model/solver/dry_friction.h (h = 1: the
/// relative speeds are algebraic). With every differential open at r = 1/2 this is HalfShafts.

#include <array>

#include "model/solver/force_element.h"
#include "model/vehicle/differential/differential_tree.h"
#include "model/vehicle/driven_shafts.h"
#include "model/vehicle/vehicle_inputs.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle::differential {

using LeafVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxLeaves, 1>;
using DiffVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDifferentials, 1>;
using LeafSquare = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxLeaves, kMaxLeaves>;

/// The tree at one state: relative speeds, shaft torques, which differentials turn as one.
struct ShaftSolution {
  DiffVector delta_radps;
  LeafVector torque_nm;  ///< per leaf (driven wheel in the tree's order)
  LeafSquare s;          ///< S = G~ K~^-1 G~^T (only when asked for: the partials)
  std::array<bool, kMaxDifferentials> fixed{};  ///< locked, or its clutch sticks
};

class DifferentialShafts final : public solver::ForceElement<Eigen::Dynamic>, public DrivenShafts {
 public:
  /// The twists are state.shaft_twist_rad (one per driven wheel), the spins state.spin_radps, the
  /// carrier speed the workspace's.
  DifferentialShafts(const VehicleParams& p, VehicleState& state, const VehicleWorkspace& work);

  /// The step's locks (kind, or the driver's lock inputs) and clutch capacities (from the input
  /// torques of the step's start: the last step's shaft torques), frozen over the step.
  void begin_step(const VehicleInputs& inputs) noexcept;

  [[nodiscard]] Eigen::Index state_size() const noexcept override { return tree_.leaf_count; }
  [[nodiscard]] Vector& state() noexcept override { return state_.shaft_twist_rad; }
  void rate(const Vector& s, Vector& f) const noexcept override;
  bool rate_jacobian(const Vector& s, Matrix& df_ds) const noexcept override;

  [[nodiscard]] int count() const noexcept override { return tree_.leaf_count; }
  [[nodiscard]] int wheel(int i) const noexcept override {
    return tree_.wheel[static_cast<std::size_t>(i)];
  }
  void wheel_torques(double carrier_radps, double h, std::array<double, kMaxWheels>& torque_nm,
                     std::array<double, kMaxWheels>& added_inertia_kgm2) const noexcept override;
  [[nodiscard]] double carrier_torque_nm(double carrier_radps) const noexcept override;

  /// The tree at twists s and carrier speed w_c, the state's wheel spins; S too if `partials`.
  void solve(const Vector& s, double carrier_radps, ShaftSolution& out,
             bool partials = false) const noexcept;
  /// Every differential's speeds and lock at the state (its twists, spins and w_c).
  void speeds(double carrier_radps,
              std::array<DifferentialReport, kMaxDifferentials>& out) const noexcept;
  [[nodiscard]] const DifferentialTree& tree() const noexcept { return tree_; }
  /// The clutch couple's capacity of the step (limited slip), T_L / 2 [N m].
  [[nodiscard]] double clutch_capacity_nm(int j) const noexcept {
    return capacity_nm_[static_cast<std::size_t>(j)];
  }

 private:
  void reduce(const std::array<bool, kMaxDifferentials>& fixed, LeafMatrix& g,
              DiffMatrix& k) const noexcept;
  void clutches(const LeafVector& x, std::array<bool, kMaxDifferentials>& fixed,
                DiffVector& lambda) const noexcept;

  DifferentialTree tree_;
  VehicleState& state_;
  const VehicleWorkspace& work_;
  double c_;
  double d_;
  std::array<bool, kMaxDifferentials> locked_{};
  std::array<double, kMaxDifferentials> capacity_nm_{};
};

}  // namespace rig::model::vehicle::differential
