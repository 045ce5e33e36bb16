#pragma once
/// @file
/// A rigid axle on two five-link leaf springs (sec. 2.3, Fig. 9; model/vehicle/leaf_spring),
/// through the framework's AxleSuspension seam: one leaf per side at +-spring_track/2, its seat
/// at heave +- (spring_track/2) roll above its rest height.
///
/// The leaf's seat also moves fore-aft (x) and winds up (pitch), for which the rigid axle has
/// no coordinates. They are condensed quasi-statically: each evaluation finds the (x, pitch) at
/// which the two leaves balance the housing's fore-aft force and pitch moment
/// (AxleHousingLoad: tires, brakes, drive reaction), by Newton on those two unknowns around
/// the leaves' own warm-started Newton, and hands heave and roll the leaves' vertical forces
/// with the condensed stiffness (the Schur complement K_ee - K_ei K_ii^-1 K_ie). Why not two
/// more framework coordinates: the axle's fore-aft and wind-up modes (leaf fore-aft rate
/// ~3 MN/m and ~90 kN m/rad on a 100 kg axle with ~10 kg m^2 about y: 30-50 Hz) are far above
/// the ride's and would need their own inertia data and a 4 x 4 leaf of the arrowhead; the
/// paper's quasi-static leaf makes the same choice for the leaf's own links. The axle's
/// fore-aft travel (mm) does not move the wheel centres in the framework.
///
/// Warm start: (x, pitch) from the last balance plus its first-order change with the housing
/// load and (heave, roll); each leaf from its own state. At most kMaxBalanceEvaluations leaf
/// evaluations per side (each at most LeafSpringParams::max_iterations Newton iterations); the
/// remaining imbalance is taken out to first order (q += K_ei d, d the Newton step), so what
/// the framework sees is the balanced leaf to second order. No allocation.
///
/// The state (both leaves, x, pitch, the last balance) lives in VehicleState (LeafAxleState):
/// the element holds a reference to its slot, as the framework holds the state. forces()
/// without a load (the Jacobians, the wheels' reported spring force) is the last balance's
/// first-order model at (heave, roll): its condensed stiffness is one step old in the Jacobian.

#include "model/vehicle/leaf_axle_state.h"
#include "model/vehicle/leaf_spring/leaf_spring.h"
#include "model/vehicle/rigid_axle.h"

namespace rig::model::vehicle {

class LeafBalance;

class LeafAxleSuspension final : public AxleSuspension {
 public:
  static constexpr int kMaxBalanceEvaluations = 3;
  /// Axle `axle` of `a.leaf_spring`; dampers, stops and bar as SpringDamperAxleSuspension's
  /// (the springs are the leaves); the static spring forces each side (the framework's
  /// preloads) set the leaves' rest heights. Throws std::invalid_argument if the leaves find
  /// no rest under them (construction time).
  LeafAxleSuspension(int axle, const AxleParams& a, double preload_left_n, double preload_right_n,
                     LeafAxleState& state);

  void forces(double heave_m, double roll_rad, double heave_rate_mps, double roll_rate_radps,
              AxleSuspensionForces& out) const noexcept override;
  void forces_under_load(double heave_m, double roll_rad, double heave_rate_mps,
                         double roll_rate_radps, const AxleHousingLoad& load,
                         AxleSuspensionForces& out) const noexcept override;

  /// In a leaf balance (leaf_balance.h) as its front (role 0) or rear (1) axle: the group
  /// balances both axles in prepare(), forces_under_load() then hands on its result.
  void join(const LeafBalance& group, int role) noexcept {
    group_ = &group;
    role_ = role;
  }
  void prepare(double heave_m, double roll_rad,
               const AxleHousingLoad& load) const noexcept override;
  /// The slot in VehicleState (the group writes it), the leaves' half spacing.
  [[nodiscard]] LeafAxleState& slot() const noexcept { return *state_; }
  [[nodiscard]] double half_track_m() const noexcept { return half_track_m_; }
  /// Make the slot's state the rest (the group settles its rockers after construction).
  void set_rest(const LeafAxleState& rest) noexcept { rest_ = rest; }

  /// The state at rest (design height, no housing load): a reset copies it into the slot.
  [[nodiscard]] const LeafAxleState& rest_state() const noexcept { return rest_; }
  void place_at_rest() const noexcept { *state_ = rest_; }
  [[nodiscard]] const leaf_spring::LeafSpring& leaf() const noexcept { return leaf_; }
  /// Each leaf's seat height (from the free leaf) at heave 0, roll 0.
  [[nodiscard]] double rest_seat_z_m(int side) const noexcept {
    return rest_seat_z_m_[static_cast<std::size_t>(side)];
  }

 private:
  /// One evaluation of both leaves at (x, pitch) and the seat heights; the balance residual
  /// (their fore-aft force and moment plus the load), the stiffness over (x, pitch, heave,
  /// roll).
  struct Both {
    std::array<leaf_spring::LeafForces, 2> leaf;
    Eigen::Vector4d generalized;  ///< on (x, pitch, heave, roll)
    Eigen::Vector2d residual;     ///< generalized.head(2) + load
    Eigen::Matrix4d stiffness;    ///< d generalized / d(x, pitch, heave, roll)
  };
  Both evaluate(const Eigen::Vector2d& balance, double heave_m, double roll_rad,
                const Eigen::Vector2d& load, LeafAxleState& s) const noexcept;
  /// Balance the housing's load from the warm start and keep the result in `s`.
  void balance(double heave_m, double roll_rad, const Eigen::Vector2d& load,
               LeafAxleState& s) const noexcept;
  void settle_rest(double preload_left_n, double preload_right_n);

  leaf_spring::LeafSpring leaf_;
  SpringDamperAxleSuspension others_;  ///< dampers, stops, bar (spring rate and preload 0)
  double half_track_m_ = 0;
  std::array<double, 2> rest_seat_z_m_{};
  LeafAxleState rest_;
  LeafAxleState* state_;  ///< its slot in VehicleState (outlives the element)
  const LeafBalance* group_ = nullptr;
  int role_ = 0;
};

}  // namespace rig::model::vehicle
