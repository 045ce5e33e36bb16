#pragma once
/// @file
/// Leaf balance (issue 17 item 3): a "four-spring" tandem whose two leaf-sprung rigid axles share
/// their load through a rocker on each side. Per side, the front axle's leaf has its front eye on
/// a fixed hanger and its shackle pin on the rocker's front end; the rear axle's leaf has its
/// front eye on the rocker's rear end and its shackle on a fixed rear hanger; the rocker is
/// pivoted on the frame at pivot_x_m between them. `[[load_sharing]] kind = "leaf_balance"`.
///
/// The rocker is massless and quasi-static: its angle beta (per side, front end up +) is where
/// the moments of the two leaf ends about the pivot balance, x_1 F_1z + x_2 F_2z = 0 (x from
/// the pivot, F the leaves' vertical forces on the frame at the pin and at the eye). Its ends
/// are at the pivot's height and move vertically (dz = beta x_end, first order; the fore-aft
/// end forces have no lever): a leaf with its rocker end lifted is the same leaf turned about
/// its fixed end (leaf_spring/turned_leaf.h). Statics: each leaf puts s/L
/// (front leaf, at its pin) and (L - s)/L (rear leaf, at its eye) of its seat load on the rocker,
/// which balances them by its arms a_1, a_2: W_1 (s_1/L_1) a_1 = W_2 ((L_2 - s_2)/L_2) a_2 - the
/// tandem's split is statically determinate, whatever the leaves' rates.
///
/// The coupling: the framework evaluates each axle's suspension alone (arrowhead: an axle couples
/// only to the body), so the balance is a group element, evaluated once per force evaluation
/// when both axles have told it their (heave, roll) and housing load (AxleSuspension::prepare).
/// It solves both axles' condensed coordinates and the two rocker angles together,
/// u = (x_1, pitch_1, x_2, pitch_2, beta_l, beta_r): Newton on the 6 x 6 stiffness of the four
/// leaves, warm-started (u from the last balance moved on to first order with the inputs), to
/// the tolerances of leaf_balance.cpp, at most kMaxEvaluations evaluations of each leaf; what is
/// left is taken out to first order. Each axle then gets the forces on its (heave, roll) and the
/// diagonal block of the condensed stiffness (K_ee - K_eu K_uu^-1 K_ue); the cross block
/// (axle 1 <-> axle 2, through the rockers) is left out of the step's Jacobian - it would couple
/// two leaves of the arrowhead - as load_sharing's cross terms are: the forces are exact, only
/// the Newton step of the coupled integrator sees a slightly softer tandem. No allocation.
///
/// Without torque rods the leaves take the housings' brake and drive reactions, and the rocker
/// passes them on: a housing moment T and fore-aft force F_x (at h below the eyes) change the
/// front leaf's pin force by (T - h F_x)/L_1 and the rear leaf's eye force by -(T - h F_x)/L_2,
/// so braking moves load from the first axle to the second, W_2 - W_1 = 2 sum (T - h F_x)/L per
/// side (with L/2 seats) - on a lightly loaded solo tandem enough to lift the first axle.
/// `torque_rods = true`: rods locate the axles and take those loads to the frame (the framework
/// passes the wheels' forces to the body as ever); the leaves balance no housing load.

#include <array>

#include <Eigen/Core>

#include "model/vehicle/leaf_axle.h"
#include "model/vehicle/leaf_balance_geometry.h"
#include "model/vehicle/leaf_balance_state.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::model::vehicle {

class LeafBalance {
 public:
  static constexpr int kMaxEvaluations = 3;  // as a single leaf axle's balance
  using Vector6d = LeafBalanceState::Vector6d;
  using Matrix6d = Eigen::Matrix<double, 6, 6>;

  /// The group of `front` and `rear` (adjacent axles of `p`, front first). Settles the rockers at
  /// rest from the axles' rest states, which it updates in their slots (the caller makes them
  /// the axles' rest). Throws std::invalid_argument if they find no balance.
  LeafBalance(const VehicleParams& p, int front_axle, double pivot_x_m,
              const LeafAxleSuspension& front, const LeafAxleSuspension& rear,
              LeafBalanceState& state);

  /// Axle `role` (0 front, 1 rear) tells its inputs; the rear's call balances the group.
  void take(int role, double heave_m, double roll_rad, const AxleHousingLoad& load) const noexcept;
  /// Balances the group at inputs e = (heave_1, roll_1, heave_2, roll_2) and housing loads
  /// (F_x1, M_y1, F_x2, M_y2); writes both axles' slots and its own.
  void balance(const Eigen::Vector4d& e, const Eigen::Vector4d& load) const noexcept;

  [[nodiscard]] const LeafBalanceGeometry& geometry() const noexcept { return geometry_; }
  [[nodiscard]] const LeafBalanceState& rest_state() const noexcept { return rest_; }
  void place_at_rest() const noexcept { *state_ = rest_; }

 private:
  using Vector10d = Eigen::Matrix<double, 10, 1>;
  using Matrix10d = Eigen::Matrix<double, 10, 10>;
  /// The four leaves at (u, e): generalized forces on (u, e), their stiffness, the residual.
  struct Group {
    Vector10d q;
    Matrix10d stiffness;
    Vector6d residual;
    std::array<std::array<double, 2>, 2> spring_n{};  ///< [axle][side], compression +
    std::array<std::array<int, 2>, 2> iterations{};
  };
  [[nodiscard]] Group evaluate(const Vector6d& u, const Eigen::Vector4d& e,
                               const Eigen::Vector4d& load) const noexcept;
  void finish(const Group& g, const Vector6d& u, const Vector6d& step, const Matrix6d& kuu_inv,
              const Eigen::Vector4d& e, const Eigen::Vector4d& load) const noexcept;

  std::array<const LeafAxleSuspension*, 2> axle_{};
  LeafBalanceGeometry geometry_;
  std::array<double, 2> turn_per_beta_{};  ///< alpha = this x beta, per leaf (front, rear)
  bool torque_rods_ = false;               ///< the housings' loads go to the frame through rods
  std::array<double, 2> end_x_m_{};        ///< each leaf's rocker end from the pivot (+ ahead)
  LeafBalanceState rest_;
  LeafBalanceState* state_;
};

}  // namespace rig::model::vehicle
