#include "model/vehicle/leaf_balance.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/solver/fixed_lu.h"
#include "model/vehicle/leaf_spring/turned_leaf.h"

namespace rig::model::vehicle {
namespace {

namespace ls = leaf_spring;

/// Balanced when the leaves take each housing's load and the rockers' moments vanish to within
/// these (as the single leaf axle's, leaf_axle.cpp); what is left is taken out to first order.
/// The rocker's moment tolerance against its ~2 kN m per end: 2.5e-4.
constexpr double kForceTolerance = 2.0;   // N
constexpr double kMomentTolerance = 0.5;  // N m

bool within_tolerance(const LeafBalance::Vector6d& r) {
  return std::abs(r(0)) <= kForceTolerance && std::abs(r(2)) <= kForceTolerance &&
         std::abs(r(1)) <= kMomentTolerance && std::abs(r(3)) <= kMomentTolerance &&
         std::abs(r(4)) <= kMomentTolerance && std::abs(r(5)) <= kMomentTolerance;
}

bool rods_of(const VehicleParams& p, int front_axle) {
  for (const LoadSharingParams& g : p.load_sharing)
    if (g.kind == LoadSharingKind::kLeafBalance && g.first_axle == front_axle) return g.torque_rods;
  return false;
}

}  // namespace

LeafBalance::LeafBalance(const VehicleParams& p, int front_axle, double pivot_x_m,
                         const LeafAxleSuspension& front, const LeafAxleSuspension& rear,
                         LeafBalanceState& state)
    : axle_{&front, &rear},
      geometry_(leaf_balance_geometry(p.axles[static_cast<std::size_t>(front_axle)],
                                      p.axles[static_cast<std::size_t>(front_axle) + 1],
                                      pivot_x_m)),
      torque_rods_(rods_of(p, front_axle)),
      state_(&state) {
  // front leaf: its pin on the rocker, turned about its eye; rear leaf: its eye on the rocker,
  // turned about its pin. alpha = dz / (x_moving - x_fixed), dz = beta x (x from the pivot)
  const ls::LeafGeometry& gf = front.leaf().geometry();
  const ls::LeafGeometry& gr = rear.leaf().geometry();
  turn_per_beta_ = {geometry_.front_arm_m / (gf.pin_frame_m.x() - gf.eye_frame_m.x()),
                    -geometry_.rear_arm_m / (gr.eye_frame_m.x() - gr.pin_frame_m.x())};
  end_x_m_ = {geometry_.front_arm_m, -geometry_.rear_arm_m};
  rest_.first_axle = front_axle;
  const LeafAxleState& s1 = front.slot();
  const LeafAxleState& s2 = rear.slot();
  rest_.u << s1.x_m, s1.pitch_rad, s2.x_m, s2.pitch_rad, 0, 0;
  *state_ = rest_;
  // settle the rockers at rest (a construction-time loop: each balance takes kMaxEvaluations)
  for (int n = 0; n < 100; ++n) {
    balance(Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero());
    if (state_->evaluations == 1 &&
        within_tolerance(
            evaluate(state_->u, Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero()).residual)) {
      rest_ = *state_;
      return;
    }
  }
  throw std::invalid_argument("axles " + std::to_string(front_axle + 1) + " and " +
                              std::to_string(front_axle + 2) +
                              ": the leaf balance finds no rest under the static loads");
}

void LeafBalance::take(int role, double heave_m, double roll_rad,
                       const AxleHousingLoad& load) const noexcept {
  LeafBalanceState& s = *state_;
  const Eigen::Index k = 2 * static_cast<Eigen::Index>(role);
  s.next_at.segment<2>(k) = Eigen::Vector2d(heave_m, roll_rad);
  s.next_load.segment<2>(k) =
      torque_rods_ ? Eigen::Vector2d::Zero() : Eigen::Vector2d(load.force_x_n, load.moment_y_nm);
  if (role == 1) balance(s.next_at, s.next_load);
}

LeafBalance::Group LeafBalance::evaluate(const Vector6d& u, const Eigen::Vector4d& e,
                                         const Eigen::Vector4d& load) const noexcept {
  Group g;
  g.q.setZero();
  g.stiffness.setZero();
  for (Eigen::Index a = 0; a < 2; ++a) {
    const LeafAxleSuspension& axle = *axle_[static_cast<std::size_t>(a)];
    LeafAxleState& slot = axle.slot();
    for (Eigen::Index side = 0; side < 2; ++side) {
      const double lever = side == 0 ? axle.half_track_m() : -axle.half_track_m();
      // (x, z, pitch, alpha) = M (u, e) + (0, rest height, 0, 0): M selects five of the ten
      // unknowns, unknown col[j] entering pose row kRow[j] with factor coef[j]; applied by
      // index (as dense 4 x 10 products these went through Eigen's general matrix kernels, 10 k
      // instructions per step; each sum has at most two non-zero terms, so the same bits)
      const std::array<Eigen::Index, 5> col = {2 * a, 6 + 2 * a, 7 + 2 * a, 2 * a + 1, 4 + side};
      constexpr std::array<Eigen::Index, 5> kRow = {0, 1, 1, 2, 3};
      const std::array<double, 5> coef = {1.0, 1.0, lever, 1.0,
                                          turn_per_beta_[static_cast<std::size_t>(a)]};
      const Eigen::Vector4d pose(
          u(2 * a), e(2 * a) + lever * e(2 * a + 1) + axle.rest_seat_z_m(static_cast<int>(side)),
          u(2 * a + 1), coef[4] * u(4 + side));
      const ls::TurnedLeafForces t = ls::evaluate_turned(
          axle.leaf(), pose.head<3>(), pose(3), a == 0 ? ls::MovingEnd::kPin : ls::MovingEnd::kEye,
          slot.leaf[static_cast<std::size_t>(side)]);
      // the axle's rows: the turned leaf's generalized forces (M^T Q, M^T K M); the rocker's row:
      // the moment of the leaf's vertical force at its end about the pivot (not Q_alpha:
      // turned_leaf.h)
      const double x_end = end_x_m_[static_cast<std::size_t>(a)];
      Eigen::Matrix<double, 4, 5> rows;  // d(Q_x, Q_z, Q_pitch, rocker moment) / d(kCol)
      for (std::size_t j = 0; j < col.size(); ++j) {
        rows.col(static_cast<Eigen::Index>(j)).head<3>() =
            t.stiffness.col(kRow[j]).head<3>() * coef[j];
        rows(3, static_cast<Eigen::Index>(j)) = x_end * t.d_end_force(1, kRow[j]) * coef[j];
      }
      for (std::size_t i = 0; i < 4; ++i) {  // the axle's unknowns: M^T's rows
        const auto r = static_cast<Eigen::Index>(kRow[i]);
        g.q(col[i]) += coef[i] * t.q(r);
        for (std::size_t j = 0; j < col.size(); ++j)
          g.stiffness(col[i], col[j]) += coef[i] * rows(r, static_cast<Eigen::Index>(j));
      }
      g.q(4 + side) += x_end * t.end_force_n(1);
      for (std::size_t j = 0; j < col.size(); ++j)
        g.stiffness(4 + side, col[j]) += rows(3, static_cast<Eigen::Index>(j));
      g.spring_n[static_cast<std::size_t>(a)][static_cast<std::size_t>(side)] = -t.q(1);
      g.iterations[static_cast<std::size_t>(a)][static_cast<std::size_t>(side)] = t.leaf.iterations;
    }
  }
  g.residual = g.q.head<6>();
  g.residual.head<4>() += load;
  return g;
}

void LeafBalance::balance(const Eigen::Vector4d& e, const Eigen::Vector4d& load) const noexcept {
  LeafBalanceState& s = *state_;
  // warm start: the last balance moved on to first order with the inputs
  Vector6d u = s.u;
  const Vector6d predicted = u + s.du_de * (e - s.at) + s.du_dload * (load - s.load);
  if (predicted.allFinite()) u = predicted;
  std::array<std::array<int, 2>, 2> iterations{};
  Group g;
  Vector6d step;
  Matrix6d kuu_inv;
  s.evaluations = 0;
  for (;;) {
    g = evaluate(u, e, load);
    ++s.evaluations;
    for (std::size_t a = 0; a < 2; ++a)
      for (std::size_t k = 0; k < 2; ++k) iterations[a][k] += g.iterations[a][k];
    kuu_inv = solver::FixedLU<6>(Matrix6d(g.stiffness.topLeftCorner<6, 6>())).inverse();
    step = -kuu_inv * g.residual;
    if (within_tolerance(g.residual) || s.evaluations >= kMaxEvaluations || !step.allFinite())
      break;
    u += step;
  }
  if (!step.allFinite()) step.setZero();
  finish(g, u, step, kuu_inv, e, load);
  for (std::size_t a = 0; a < 2; ++a) {
    LeafAxleState& slot = axle_[a]->slot();
    slot.iterations = iterations[a];
    slot.balance_evaluations = s.evaluations;
  }
}

void LeafBalance::finish(const Group& g, const Vector6d& u, const Vector6d& step,
                         const Matrix6d& kuu_inv, const Eigen::Vector4d& e,
                         const Eigen::Vector4d& load) const noexcept {
  LeafBalanceState& s = *state_;
  const Eigen::Matrix<double, 6, 4> kue = g.stiffness.topRightCorner<6, 4>();
  const Eigen::Matrix<double, 4, 6> keu = g.stiffness.bottomLeftCorner<4, 6>();
  s.du_de = -kuu_inv * kue;
  s.du_dload = -kuu_inv.leftCols<4>();
  // what is left of the imbalance taken out to first order; the Schur complement
  const Eigen::Vector4d q = g.q.tail<4>() + keu * step;
  const Eigen::Matrix4d dq_de = g.stiffness.bottomRightCorner<4, 4>() + keu * s.du_de;
  s.u = u + step;
  s.at = e;
  s.load = load;
  s.moment_residual_nm = {g.residual(4), g.residual(5)};
  for (Eigen::Index a = 0; a < 2; ++a) {
    LeafAxleState& slot = axle_[static_cast<std::size_t>(a)]->slot();
    slot.x_m = s.u(2 * a);
    slot.pitch_rad = s.u(2 * a + 1);
    slot.at = e.segment<2>(2 * a);
    slot.load = load.segment<2>(2 * a);
    slot.q = q.segment<2>(2 * a);
    slot.dq_dy = dq_de.block<2, 2>(2 * a, 2 * a);  // the cross block lagged (header)
    slot.spring_n = g.spring_n[static_cast<std::size_t>(a)];
  }
}

}  // namespace rig::model::vehicle
