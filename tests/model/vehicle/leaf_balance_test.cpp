// Leaf balance (issue 17 item 3, model/vehicle/leaf_balance.h): a rocker between a tandem's two
// leaf springs on each side. Against independent numbers: the turned leaf's and the group's
// partials against finite differences; the leaf tractor's static axle loads against the hand
// calculation (tests/support/static_axle_loads.h: the rocker's statics from the leaves' s/L and
// its arms, the steer axle and the tandem by the lever rule), a centred rocker on equal leaves
// sharing equally, an off-centre pivot moving the split as its arms say, whatever the rates;
// the rocker's geometry check; braking (the tandem keeps its load, the balance's evaluations and
// the leaves' Newton in their limits, no allocation).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/vehicle/leaf_balance.h"
#include "model/vehicle/leaf_spring/turned_leaf.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/driver_inputs.h"
#include "tests/support/static_axle_loads.h"
#include "tests/support/vehicle_rest.h"

namespace rig::model::vehicle {
namespace {

namespace ls = leaf_spring;

/// The leaf tractor (its tandem on a rocker per side: 1.05 m leaves, so that the front leaf's
/// pin lies ahead of the rear leaf's eye, the pivot midway), the pivot moved by offset_m.
VehicleParams balanced_tractor(double offset_m = 0) {
  VehicleParams p =
      io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/tractor-6x4-leaf.toml");
  EXPECT_EQ(p.load_sharing.size(), 1u);
  EXPECT_EQ(p.load_sharing[0].kind, LoadSharingKind::kLeafBalance);
  p.load_sharing[0].pivot_x_m += offset_m;
  return p;
}

TEST(TurnedLeaf, PartialsMatchFiniteDifferencesAndNoTurnIsTheLeaf) {
  const VehicleParams p = balanced_tractor();
  const ls::LeafSpring leaf(p.axles[1].leaf_spring);
  ls::LeafState s;
  ASSERT_TRUE(leaf.settle(ls::SeatPose(-0.01, 0.07, 0.002), s));
  const Eigen::Vector2d eye = leaf.geometry().eye_frame_m;
  const ls::MovingEnd pin = ls::MovingEnd::kPin;  // turned about the eye
  // no turn: the leaf's own forces
  ls::LeafState s0 = s;
  const ls::LeafForces plain = leaf.evaluate(ls::SeatPose(-0.01, 0.07, 0.002), s0);
  ls::LeafState s1 = s;
  const ls::TurnedLeafForces t0 =
      ls::evaluate_turned(leaf, ls::SeatPose(-0.01, 0.07, 0.002), 0.0, pin, s1);
  EXPECT_LT((t0.q.head<3>() - plain.on_axle).norm(), 1e-9 * plain.on_axle.norm());
  // turned by 4 mrad: central differences of q over (x, z, pitch, alpha)
  const Eigen::Vector4d at(-0.01, 0.07, 0.002, 0.004);
  const auto q_at = [&](const Eigen::Vector4d& v) {
    ls::LeafState w = s;
    for (int k = 0; k < 20; ++k) (void)ls::evaluate_turned(leaf, v.head<3>(), v(3), pin, w);
    return ls::evaluate_turned(leaf, v.head<3>(), v(3), pin, w);
  };
  const ls::TurnedLeafForces t = q_at(at);
  ASSERT_TRUE(t.leaf.converged);
  Eigen::Matrix4d fd;
  Eigen::Matrix<double, 2, 4> fd_end;
  for (int j = 0; j < 4; ++j) {
    const double h = 1e-6;
    const ls::TurnedLeafForces up = q_at(at + h * Eigen::Vector4d::Unit(j));
    const ls::TurnedLeafForces down = q_at(at - h * Eigen::Vector4d::Unit(j));
    fd.col(j) = (up.q - down.q) / (2 * h);
    fd_end.col(j) = (up.end_force_n - down.end_force_n) / (2 * h);
  }
  const double err = (t.stiffness - fd).norm() / fd.norm();
  const double err_end = (t.d_end_force - fd_end).norm() / fd_end.norm();
  std::printf(
      "turned leaf: q = (%.1f N, %.1f N, %.1f N m, %.1f N m); |K - FD| / |FD| = %.2e, "
      "pin force's %.2e\n",
      t.q(0), t.q(1), t.q(2), t.q(3), err, err_end);
  EXPECT_LT(err, 1e-5);
  EXPECT_LT(err_end, 1e-5);
  // the energy's Hessian: symmetric
  EXPECT_LT((t.stiffness - t.stiffness.transpose()).norm(), 1e-9 * t.stiffness.norm());
  // q on alpha is minus the moment about the fixed eye of the leaf's force on the frame at its
  // moving end (the pin; the leaf and shackle a body in equilibrium), in the leaf's axes
  const Eigen::Vector2d pin_arm = leaf.geometry().pin_frame_m - eye;
  const Eigen::Vector2d f = t.leaf.on_frame_at_pin_n;
  EXPECT_NEAR(t.q(3), pin_arm.x() * f.y() - pin_arm.y() * f.x(), 1e-6 * std::abs(t.q(3)));
  // and the end force in frame axes is the leaf's turned back by alpha
  EXPECT_NEAR(t.end_force_n.y(), std::sin(at(3)) * f.x() + std::cos(at(3)) * f.y(),
              1e-9 * f.norm());
}

/// Axle a's load on the road.
double axle_load_n(VehicleModel& m, int a) {
  return m.wheel_load_n(2 * a) + m.wheel_load_n(2 * a + 1);
}

/// The steer axle within 0.1 % of the hand calculation, the tandem (the other support) too, and
/// each tandem axle within 0.1 % of the tandem's load (the frame's settled pitch moves ~15 N from
/// the last axle to the first: the hand calculation ignores the free bodies' heights, as
/// tractor_leaf_test says; on the lighter tandem axle that is 0.1 % of its own load).
void expect_hand_loads(const VehicleParams& p, VehicleModel& m) {
  const std::array<double, 6> spring = test::static_spring_loads_n(p);
  const double g = p.road.gravity_mps2;
  std::array<double, 3> hand{};
  for (int a = 0; a < 3; ++a) {
    const auto k = static_cast<std::size_t>(a);
    hand[k] = spring[k] + 2 * p.axles[k].unsprung_mass_kg * g;
    const double load = axle_load_n(m, a);
    std::printf("axle %d: %.1f N = %.3f t (hand %.1f N, %+.4f %%)\n", a + 1, load, load / g / 1e3,
                hand[k], 100 * (load / hand[k] - 1));
    EXPECT_NEAR(load, hand[k], 1e-3 * (a == 0 ? hand[0] : hand[1] + hand[2])) << "axle " << a + 1;
  }
  const double tandem = axle_load_n(m, 1) + axle_load_n(m, 2);
  EXPECT_NEAR(tandem, hand[1] + hand[2], 1e-3 * (hand[1] + hand[2]));
  const LeafBalanceState& b = m.state().leaf_balances[0];
  std::printf("rocker %.3f / %.3f mrad, moment residual %.3f / %.3f N m\n", 1e3 * b.u(4),
              1e3 * b.u(5), b.moment_residual_nm[0], b.moment_residual_nm[1]);
  EXPECT_EQ(b.first_axle, 1);
  EXPECT_LE(std::abs(b.moment_residual_nm[0]), 0.5);
  EXPECT_LE(std::abs(b.moment_residual_nm[1]), 0.5);
}

TEST(LeafBalance, CentredRockerOnEqualLeavesSharesTheTandemEqually) {
  const VehicleParams p = balanced_tractor();
  VehicleModel m(p, 1e-3);
  Signals s = test::all_driver_inputs();
  test::rest(m, s, 1.0);  // settled standing, braked: the loads after 1 s
  expect_hand_loads(p, m);
  const double l2 = axle_load_n(m, 1), l3 = axle_load_n(m, 2);
  std::printf("tandem %.1f / %.1f N (%+.3f %%)\n", l2, l3, 100 * (l3 / l2 - 1));
  EXPECT_NEAR(l3, l2, 0.02 * l2);  // the load-sharing criterion
  EXPECT_NEAR(l3, l2, 2e-3 * l2);  // and the hand's equal split, to 0.1 % of the tandem
}

TEST(LeafBalance, OffCentrePivotSplitsTheTandemByTheRockersArms) {
  // 30 mm ahead of centre: the rear axle's arm grows, it carries more; and with a stiffer front
  // tandem leaf the split stays the rocker's (statically determinate)
  VehicleParams p = balanced_tractor(0.03);
  p.axles[1].leaf_spring.front_bending_stiffness_nm2 = 6000.0;
  p.axles[1].leaf_spring.rear_bending_stiffness_nm2 = 6000.0;
  VehicleModel m(p, 1e-3);
  Signals s = test::all_driver_inputs();
  test::rest(m, s, 1.0);  // settled standing, braked: the loads after 1 s
  expect_hand_loads(p, m);
  EXPECT_GT(axle_load_n(m, 1), 1.05 * axle_load_n(m, 2));
}

TEST(LeafBalance, CondensedStiffnessMatchesFiniteDifferences) {
  const VehicleParams p = balanced_tractor();
  const double preload = 20000.0;
  LeafAxleState slot1, slot2;
  LeafBalanceState state;
  LeafAxleSuspension front(1, p.axles[1], preload, preload, slot1);
  LeafAxleSuspension rear(2, p.axles[2], preload, preload, slot2);
  const LeafBalance b(p, 1, p.load_sharing[0].pivot_x_m, front, rear, state);
  const Eigen::Vector4d load(3000.0, -4000.0, 2500.0, -3500.0);  // braking: F_x, M_y per axle
  const Eigen::Vector4d e0(0.004, 0.002, -0.003, -0.001);
  const auto q_at = [&](const Eigen::Vector4d& e) {
    for (int k = 0; k < 10; ++k) b.balance(e, load);  // converged
    Eigen::Vector4d q;
    q << slot1.q, slot2.q;
    return q;
  };
  (void)q_at(e0);
  Eigen::Matrix4d analytic = Eigen::Matrix4d::Zero();
  analytic.topLeftCorner<2, 2>() = slot1.dq_dy;
  analytic.bottomRightCorner<2, 2>() = slot2.dq_dy;
  EXPECT_LE(state.evaluations, LeafBalance::kMaxEvaluations);
  Eigen::Matrix4d fd;
  for (int j = 0; j < 4; ++j) {
    const double h = 1e-5;
    fd.col(j) =
        (q_at(e0 + h * Eigen::Vector4d::Unit(j)) - q_at(e0 - h * Eigen::Vector4d::Unit(j))) /
        (2 * h);
  }
  // the diagonal blocks (each axle's own): the framework's Jacobian; the cross blocks (through
  // the rockers) are lagged - printed, with their size against the diagonal
  Eigen::Matrix4d diag = fd;
  diag.topRightCorner<2, 2>().setZero();
  diag.bottomLeftCorner<2, 2>().setZero();
  const double err = (analytic - diag).norm() / diag.norm();
  std::printf("condensed: |K - FD| / |FD| (diagonal blocks) = %.2e; cross / diagonal heave %.3f\n",
              err, fd(0, 2) / fd(0, 0));
  EXPECT_LT(err, 1e-4);
  // the rockers couple the axles: raising the front axle loads the rear one (the rear leaf's
  // eye pushed down), about as much as itself (a centred rocker shares the heave)
  EXPECT_LT(fd(2, 0), 0.5 * fd(0, 0));
}

TEST(LeafBalance, TheRockersEndsMustBeOnEitherSideOfThePivot) {
  VehicleParams p = balanced_tractor();
  const LeafBalanceGeometry g = leaf_balance_geometry(p.axles[1], p.axles[2], -2.3074875);
  // the front leaf's pin 15 mm behind its rear eye (the shackle at -0.1 rad), the rear leaf's eye
  // at its seat_from_front_eye ahead of the axle: arms 0.1425 m, shares 1/2
  EXPECT_NEAR(g.front_end_x_m, -1.625 - 0.525 + 0.15 * std::sin(-0.10), 1e-9);
  EXPECT_NEAR(g.rear_end_x_m, -2.975 + 0.525, 1e-9);
  EXPECT_NEAR(g.front_arm_m, 0.1425, 2e-5);
  EXPECT_NEAR(g.rear_arm_m, 0.1425, 2e-5);
  EXPECT_EQ(g.front_share, 0.5);
  EXPECT_EQ(g.rear_share, 0.5);
  EXPECT_THROW((void)leaf_balance_geometry(p.axles[1], p.axles[2], -2.1), std::invalid_argument);
  p.axles[1].leaf_spring.eye_to_eye_m = 1.65;  // the leaves overlap: pin behind the eye
  p.axles[1].leaf_spring.seat_from_front_eye_m = 0.825;
  p.axles[2].leaf_spring.eye_to_eye_m = 1.65;
  p.axles[2].leaf_spring.seat_from_front_eye_m = 0.825;
  EXPECT_THROW((void)axle_shares(p), std::invalid_argument);
}

// Braking from 60 km/h at 3 bar (~0.3 g) to stand-still: both tandem axles keep their load (solo
// without the rocker the last one lifted off), the rockers balanced in every step, the group's
// evaluations and the leaves' Newton in their limits, no allocation.
TEST(LeafBalance, BrakingTandemKeepsBothAxlesLoadedWithinTheLimits) {
  const VehicleParams p = balanced_tractor();
  VehicleModel m(p, 1e-3);
  Signals s = test::all_driver_inputs();
  (void)m.settle(16.67);
  s[Signal::kThrottlePedal] = 0.0;
  for (int k = 0; k < 500; ++k) ASSERT_EQ(m.step(s), StepStatus::kOk);  // warm, outside
  const double static2 = axle_load_n(m, 1), static3 = axle_load_n(m, 2);
  const LeafBalanceState before = m.state().leaf_balances[0];
  const double heave_difference_before = m.state().framework_y(8) - m.state().framework_y(10);
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  int most_evaluations = 0, most_iterations = 0;
  double worst_residual = 0, least2 = 1e9, least3 = 1e9;
  double sum2 = 0, sum3 = 0, sum_beta = 0, sum_ax = 0, sum_dh = 0;
  int n = 0;
  for (int k = 0; k < 5000; ++k) {
    const double ramp = std::min(1.0, k / 300.0);
    s[Signal::kBrakePressureFront] = 3e5 * ramp;
    s[Signal::kBrakePressureRear] = 3e5 * ramp;
    ASSERT_EQ(m.step(s), StepStatus::kOk) << "t = " << m.time_s();
    const LeafBalanceState& b = m.state().leaf_balances[0];
    most_evaluations = std::max(most_evaluations, b.evaluations);
    worst_residual = std::max(
        {worst_residual, std::abs(b.moment_residual_nm[0]), std::abs(b.moment_residual_nm[1])});
    for (int a = 1; a < 3; ++a) {
      const LeafAxleState& l = m.state().leaf_axles[static_cast<std::size_t>(a)];
      most_iterations = std::max({most_iterations, l.iterations[0], l.iterations[1]});
    }
    const double l2 = axle_load_n(m, 1), l3 = axle_load_n(m, 2);
    least2 = std::min(least2, l2);
    least3 = std::min(least3, l3);
    if (k >= 1000 && k < 3000) {  // steady braking
      sum2 += l2;
      sum3 += l3;
      sum_beta += 0.5 * (b.u(4) + b.u(5));
      sum_ax += m.state().acceleration_mps2.x();
      sum_dh += m.state().framework_y(8) - m.state().framework_y(10);
      ++n;
    }
  }
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  std::printf(
      "static tandem %.0f / %.0f N; braking (a_x %.2f m/s^2) %.0f / %.0f N, rocker "
      "%.2f mrad; least %.0f / %.0f N\n",
      static2, static3, sum_ax / n, sum2 / n, sum3 / n, 1e3 * sum_beta / n, least2, least3);
  std::printf("rocker residual <= %.3f N m, evaluations <= %d, leaf iterations <= %d\n",
              worst_residual, most_evaluations, most_iterations);
  EXPECT_GT(least2, 0.3 * static2);  // no lift-off
  EXPECT_GT(least3, 0.3 * static3);
  // the hand estimate (torque rods: no housing load on the leaves): the rockers keep the four
  // leaves' loads equal, so the two axles' loads stay within their unsprung masses' inertia of
  // each other; the rocker turns by the axles' heave difference over its arm - the leaves
  // deflect alike, so the pin and the eye take up h_1 - h_2: a (beta_1 - beta_0) = dh_1 - dh_2
  // (first order; the frame's nose-down pitch p gives dh_1 - dh_2 = 1.35 m p)
  EXPECT_NEAR(sum3 / n, sum2 / n, 0.02 * sum2 / n);
  const double arm = 0.1425;  // the rocker's arms (the file's geometry, above)
  const double beta_change = sum_beta / n - 0.5 * (before.u(4) + before.u(5));
  const double hand_beta = (sum_dh / n - heave_difference_before) / arm;
  std::printf("rocker turned %.3f mrad; hand (dh_1 - dh_2) / a %.3f mrad\n", 1e3 * beta_change,
              1e3 * hand_beta);
  EXPECT_NEAR(beta_change, hand_beta, 0.1 * std::abs(hand_beta) + 1e-4);
  EXPECT_LE(worst_residual, 0.5);
  EXPECT_LE(most_evaluations, LeafBalance::kMaxEvaluations);
  EXPECT_LE(most_iterations, LeafBalance::kMaxEvaluations * 4);
}

}  // namespace
}  // namespace rig::model::vehicle
