// The five-link leaf spring (issue 17 item 2) against the finite-element beam of the same leaf
// (leaf_fe_reference.py -> leaf_fe_reference.json): vertical rate within 5 %, wind-up stiffness
// within 10 %, shackle swing and fore-aft travel within 10 %, over -1.5 kN (rebound) to 1.5 x
// the static 7.5 kN. Then the element itself: Newton iterations along a 1 ms load history,
// analytic partials vs finite differences, force = -dV/dq, the statics of the forces it returns,
// no allocation. The sources are compiled into this test with EIGEN_RUNTIME_NO_MALLOC.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "model/vehicle/leaf_spring/leaf_spring.h"
#include "tests/model/vehicle/leaf_spring/load_history.h"
#include "tests/model/vehicle/leaf_spring/reference_json.h"
#include "tests/model/vehicle/leaf_spring/van_leaf_params.h"
#include "tests/support/alloc_counter.h"

namespace {

namespace ls = rig::model::vehicle::leaf_spring;
using ls::LeafForces;
using ls::LeafSpring;
using ls::LeafState;
using ls::SeatPose;

const rig::test::FlatJson& reference() {
  static const rig::test::FlatJson json(RIG_LEAF_FE_REFERENCE);
  return json;
}

/// Evaluates until the leaf's Newton has converged at `q` (the seat may have jumped).
LeafForces converged_at(const LeafSpring& leaf, const SeatPose& q, LeafState& s) {
  LeafForces f = leaf.evaluate(q, s);
  for (int k = 0; k < 20 && !f.converged; ++k) f = leaf.evaluate(q, s);
  EXPECT_TRUE(f.converged);
  return f;
}

/// The seat pose where the leaf carries `load` (x, z force and moment on the axle from outside),
/// by Newton on the element's own partials, from the pose in `q`.
LeafForces loaded(const LeafSpring& leaf, const Eigen::Vector3d& load, SeatPose& q, LeafState& s) {
  LeafForces f;
  for (int k = 0; k < 50; ++k) {
    f = converged_at(leaf, q, s);
    const Eigen::Vector3d r = f.on_axle + load;
    if (r.cwiseAbs().maxCoeff() < 1e-7) return f;
    q -= f.d_on_axle_d_seat.lu().solve(r);
  }
  ADD_FAILURE() << "no equilibrium under the load";
  return f;
}

/// The tangent stiffnesses the FE reference reports: vertical rate and wind-up with the other
/// coordinates free (1 / compliance), wind-up with the axle held (x, z), fore-aft with it free.
struct Tangent {
  double rate_npm, windup_free_nmprad, windup_held_nmprad, fore_aft_free_npm;
};

Tangent tangent(const Eigen::Matrix3d& k) {
  const Eigen::Matrix3d c = k.inverse();
  return {1.0 / c(1, 1), 1.0 / c(2, 2), k(2, 2), 1.0 / c(0, 0)};
}

Tangent tangent(const LeafForces& f) { return tangent(Eigen::Matrix3d(-f.d_on_axle_d_seat)); }

void expect_within(double model, double fe, double fraction, const std::string& what) {
  EXPECT_LE(std::abs(model - fe), fraction * std::abs(fe))
      << what << ": model " << model << ", FE " << fe;
}

TEST(LeafSpringReference, ParametersAreTheReferencesOwn) {
  const auto p = rig::test::van_rear_leaf();
  const auto& j = reference();
  EXPECT_EQ(j.number("param_eye_to_eye_m"), p.eye_to_eye_m);
  EXPECT_EQ(j.number("param_seat_from_front_eye_m"), p.seat_from_front_eye_m);
  EXPECT_EQ(j.number("param_free_camber_m"), p.free_camber_m);
  EXPECT_EQ(j.number("param_seat_length_m"), p.seat_length_m);
  EXPECT_EQ(j.number("param_leaf_above_axle_m"), p.leaf_above_axle_m);
  EXPECT_EQ(j.number("param_front_bending_stiffness_nm2"), p.front_bending_stiffness_nm2);
  EXPECT_EQ(j.number("param_rear_bending_stiffness_nm2"), p.rear_bending_stiffness_nm2);
  EXPECT_EQ(j.number("param_shackle_length_m"), p.shackle_length_m);
  EXPECT_EQ(j.number("param_shackle_angle_free_rad"), p.shackle_angle_free_rad);
  EXPECT_EQ(j.number("param_eye_bushing_x_npm"), p.eye_bushing_x_npm);
  EXPECT_EQ(j.number("param_eye_bushing_z_npm"), p.eye_bushing_z_npm);
  EXPECT_EQ(j.number("static_load_n"), rig::test::kVanLeafStaticLoadN);
}

// Vertical load on the axle, no fore-aft force, no moment: the axle finds its own travel.
TEST(LeafSpringReference, VerticalLoadRangeMatchesTheBeam) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  const auto& j = reference();
  const auto load = j.numbers("vertical_load_n");
  const auto z = j.numbers("vertical_z_m");
  const auto x = j.numbers("vertical_x_m");
  const auto pitch = j.numbers("vertical_pitch_rad");
  const auto psi = j.numbers("vertical_shackle_rad");
  const auto rate = j.numbers("vertical_rate_npm");
  const auto wind_free = j.numbers("vertical_windup_free_nmprad");
  const auto wind_held = j.numbers("vertical_windup_held_nmprad");
  const auto stiffness = j.numbers("vertical_stiffness");  // 3 x 3 per load, row-major
  ASSERT_EQ(load.size(), 18U);
  ASSERT_EQ(stiffness.size(), 9 * load.size());
  LeafState s = leaf.free_state();
  SeatPose q = SeatPose::Zero();
  const double psi0 = leaf.params().shackle_angle_free_rad;
  for (std::size_t i = 0; i < load.size(); ++i) {
    const LeafForces f = loaded(leaf, {0.0, load[i], 0.0}, q, s);
    const Tangent t = tangent(f);
    const std::string at = " at " + std::to_string(load[i]) + " N";
    expect_within(t.rate_npm, rate[i], 0.05, "vertical rate" + at);
    expect_within(t.windup_free_nmprad, wind_free[i], 0.10, "wind-up stiffness, axle free" + at);
    expect_within(t.windup_held_nmprad, wind_held[i], 0.10, "wind-up stiffness, axle held" + at);
    const Tangent fe = tangent(Eigen::Matrix3d::Map(&stiffness[9 * i]).transpose());
    EXPECT_NEAR(fe.rate_npm, rate[i], 1e-6 * rate[i]);  // the same matrix
    expect_within(t.fore_aft_free_npm, fe.fore_aft_free_npm, 0.10, "fore-aft stiffness" + at);
    if (load[i] == 0.0) continue;
    expect_within(q(1), z[i], 0.05, "vertical travel" + at);
    expect_within(q(0), x[i], 0.10, "fore-aft travel" + at);
    expect_within(q(2), pitch[i], 0.10, "axle rotation" + at);
    expect_within(s.shackle_angle_rad() - psi0, psi[i] - psi0, 0.10, "shackle swing" + at);
  }
}

// The static load plus a brake torque: the axle winds up.
TEST(LeafSpringReference, WindUpUnderBrakeTorqueMatchesTheBeam) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  const auto& j = reference();
  const auto moment = j.numbers("windup_moment_nm");
  const auto pitch = j.numbers("windup_pitch_rad");
  const auto x = j.numbers("windup_x_m");
  LeafState s = leaf.free_state();
  SeatPose q = SeatPose::Zero();
  const double fz = rig::test::kVanLeafStaticLoadN;
  (void)loaded(leaf, {0.0, fz, 0.0}, q, s);
  const double pitch_static = q(2);
  const double x_static = q(0);
  const std::size_t mid = moment.size() / 2;
  ASSERT_EQ(moment[mid], 0.0);
  for (std::size_t i = 0; i < moment.size(); ++i) {
    (void)loaded(leaf, {0.0, fz, moment[i]}, q, s);
    if (i == mid) continue;
    const std::string at = " at " + std::to_string(moment[i]) + " N m";
    // secant wind-up stiffness from the static state, and the fore-aft shift it brings
    expect_within(moment[i] / (q(2) - pitch_static), moment[i] / (pitch[i] - pitch[mid]), 0.10,
                  "wind-up stiffness" + at);
    expect_within(q(0) - x_static, x[i] - x[mid], 0.10, "fore-aft shift" + at);
  }
}

// The element at rest: no force, no iteration, the eye on its bushing centre.
TEST(LeafSpring, FreeLeafCarriesNothing) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  LeafState s = leaf.free_state();
  const LeafForces f = leaf.evaluate(SeatPose::Zero(), s);
  EXPECT_TRUE(f.converged);
  EXPECT_EQ(f.iterations, 0);
  EXPECT_LT(f.on_axle.cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((f.eye_m - leaf.geometry().eye_frame_m).norm(), 1e-15);
  EXPECT_NEAR(leaf.geometry().eye_frame_m.x(), 0.60, 1e-15);
  EXPECT_NEAR(leaf.geometry().eye_frame_m.y(), 0.08 + 0.10, 1e-15);
}

using rig::test::leaf_history_pose;

TEST(LeafSpring, NewtonConvergesWithinFourIterationsPerMillisecond) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  LeafState s = leaf.free_state();
  SeatPose stat = SeatPose::Zero();
  (void)loaded(leaf, {0.0, rig::test::kVanLeafStaticLoadN, 0.0}, stat, s);
  std::array<int, 6> histogram{};
  for (int k = 0; k <= 10000; ++k) {
    const LeafForces f = leaf.evaluate(leaf_history_pose(stat, k), s);
    ASSERT_TRUE(f.converged) << "step " << k;
    ASSERT_LE(f.iterations, 4) << "step " << k;
    ++histogram[static_cast<std::size_t>(f.iterations)];
  }
  std::printf("iterations per step: 0: %d, 1: %d, 2: %d, 3: %d, 4: %d\n", histogram[0],
              histogram[1], histogram[2], histogram[3], histogram[4]);
  EXPECT_EQ(histogram[3] + histogram[4], 0);  // the warm start keeps it at 1-2
}

TEST(LeafSpring, SettleReachesAFarPose) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  LeafState s;
  ASSERT_TRUE(leaf.settle({-0.02, 0.12, 0.06}, s));
  LeafState direct = leaf.free_state();
  const LeafForces a = converged_at(leaf, {-0.02, 0.12, 0.06}, direct);
  const LeafForces b = leaf.evaluate({-0.02, 0.12, 0.06}, s);
  EXPECT_EQ(b.iterations, 0);
  EXPECT_LT((a.on_axle - b.on_axle).norm(), 1e-6);
}

const std::array<SeatPose, 4> kPoses{SeatPose(0.0, 0.02, 0.0), SeatPose(-0.012, 0.076, 0.034),
                                     SeatPose(-0.015, 0.115, 0.09), SeatPose(0.01, -0.02, -0.03)};

TEST(LeafSpring, PartialsMatchFiniteDifferences) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  for (const SeatPose& q : kPoses) {
    LeafState s;
    ASSERT_TRUE(leaf.settle(q, s));
    const LeafForces f = leaf.evaluate(q, s);
    Eigen::Matrix3d fd;
    Eigen::Matrix<double, 2, 3> fd_eye;
    Eigen::Matrix<double, 2, 3> fd_pin;
    constexpr double kH = 1e-6;
    for (int c = 0; c < 3; ++c) {
      LeafState sp = s;
      LeafState sm = s;
      const LeafForces p = converged_at(leaf, q + kH * SeatPose::Unit(c), sp);
      const LeafForces m = converged_at(leaf, q - kH * SeatPose::Unit(c), sm);
      fd.col(c) = (p.on_axle - m.on_axle) / (2.0 * kH);
      fd_eye.col(c) = (p.on_frame_at_eye_n - m.on_frame_at_eye_n) / (2.0 * kH);
      fd_pin.col(c) = (p.on_frame_at_pin_n - m.on_frame_at_pin_n) / (2.0 * kH);
    }
    const double scale = f.d_on_axle_d_seat.cwiseAbs().maxCoeff();
    EXPECT_LT((fd - f.d_on_axle_d_seat).cwiseAbs().maxCoeff(), 1e-6 * scale) << q.transpose();
    EXPECT_LT((fd_eye - f.d_on_frame_at_eye_d_seat).cwiseAbs().maxCoeff(), 1e-6 * scale);
    EXPECT_LT((fd_pin - f.d_on_frame_at_pin_d_seat).cwiseAbs().maxCoeff(), 1e-6 * scale);
    // a potential force: its Jacobian is symmetric
    EXPECT_LT((f.d_on_axle_d_seat - f.d_on_axle_d_seat.transpose()).cwiseAbs().maxCoeff(),
              1e-9 * scale);
  }
}

TEST(LeafSpring, ForceIsMinusTheGradientOfTheEnergy) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  for (const SeatPose& q : kPoses) {
    LeafState s;
    ASSERT_TRUE(leaf.settle(q, s));
    const LeafForces f = leaf.evaluate(q, s);
    for (int c = 0; c < 3; ++c) {
      constexpr double kH = 1e-5;
      LeafState sp = s;
      LeafState sm = s;
      const double vp = converged_at(leaf, q + kH * SeatPose::Unit(c), sp).energy_j;
      const double vm = converged_at(leaf, q - kH * SeatPose::Unit(c), sm).energy_j;
      EXPECT_NEAR(f.on_axle(c), -(vp - vm) / (2.0 * kH), 1e-5 * f.on_axle.norm() + 1e-6)
          << "coordinate " << c << " at " << q.transpose();
    }
  }
}

/// y-component of r x F in the x-z plane: the moment about +y.
double moment_y(const Eigen::Vector2d& r, const Eigen::Vector2d& f) {
  return r.y() * f.x() - r.x() * f.y();
}

// The massless leaf and shackle pass everything on: forces and moments on axle and frame balance.
TEST(LeafSpring, AxleAndFrameForcesBalance) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  for (const SeatPose& q : kPoses) {
    LeafState s;
    ASSERT_TRUE(leaf.settle(q, s));
    const LeafForces f = leaf.evaluate(q, s);
    const Eigen::Vector2d axle_force(f.on_axle(0), f.on_axle(1));
    const Eigen::Vector2d sum = axle_force + f.on_frame_at_eye_n + f.on_frame_at_pin_n;
    EXPECT_LT(sum.norm(), 1e-6 * f.on_axle.norm());
    const double moments = f.on_axle(2) + moment_y({q(0), q(1)}, axle_force) +
                           moment_y(f.eye_m, f.on_frame_at_eye_n) +
                           moment_y(leaf.geometry().pin_frame_m, f.on_frame_at_pin_n);
    EXPECT_LT(std::abs(moments), 1e-6 * f.on_axle.norm());
    // the shackle is a two-force link: its force lies along it
    const double psi = s.shackle_angle_rad();
    const Eigen::Vector2d along(std::sin(psi), std::cos(psi));
    EXPECT_LT(std::abs(moment_y(along, f.on_frame_at_pin_n)), 1e-9 * f.on_axle.norm());
  }
}

TEST(LeafSpring, EvaluateDoesNotAllocate) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  LeafState s = leaf.free_state();
  SeatPose stat = SeatPose::Zero();
  (void)loaded(leaf, {0.0, rig::test::kVanLeafStaticLoadN, 0.0}, stat, s);
  double sink = 0;
  const rig::test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);  // an Eigen heap allocation would abort here
  for (int k = 0; k < 2000; ++k) sink += leaf.evaluate(leaf_history_pose(stat, k), s).on_axle(1);
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0U);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(LeafSpring, BadParametersAreRejectedAtConstruction) {
  auto p = rig::test::van_rear_leaf();
  p.free_camber_m = 0.0;
  EXPECT_THROW(LeafSpring{p}, std::invalid_argument);
  p = rig::test::van_rear_leaf();
  p.seat_from_front_eye_m = 1.39;
  EXPECT_THROW(LeafSpring{p}, std::invalid_argument);
  p = rig::test::van_rear_leaf();
  p.rear_bending_stiffness_nm2 = std::nan("");
  EXPECT_THROW(LeafSpring{p}, std::invalid_argument);
}

// A seat pose that is not a number does not hang or pretend: it reports no convergence, and
// the state stays the last good one.
TEST(LeafSpring, NanPoseIsNotConvergedAndNotKept) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  LeafState s;
  ASSERT_TRUE(leaf.settle({-0.012, 0.076, 0.034}, s));
  const LeafForces before = leaf.evaluate({-0.012, 0.076, 0.034}, s);
  const LeafForces f = leaf.evaluate({0.0, std::nan(""), 0.0}, s);
  EXPECT_FALSE(f.converged);
  EXPECT_LE(f.iterations, 4);
  const LeafForces after = leaf.evaluate({-0.012, 0.076, 0.034}, s);
  EXPECT_TRUE(after.converged);
  EXPECT_EQ(after.iterations, 0);
  EXPECT_EQ(after.on_axle, before.on_axle);
}

// A jump from the free leaf to 1.5 x the static deflection in one call (a reset without
// settle): no convergence claimed until it has converged, a few calls, the same equilibrium.
TEST(LeafSpring, AJumpConvergesOverAFewCallsToTheSettledState) {
  const LeafSpring leaf(rig::test::van_rear_leaf());
  const SeatPose far(-0.015, 0.115, 0.052);
  LeafState settled;
  ASSERT_TRUE(leaf.settle(far, settled));
  const LeafForces reference = leaf.evaluate(far, settled);
  LeafState s = leaf.free_state();
  int calls = 1;
  LeafForces f = leaf.evaluate(far, s);
  for (; !f.converged && calls < 10; ++calls) f = leaf.evaluate(far, s);
  std::printf("converged after %d calls of at most 4 iterations\n", calls);
  ASSERT_TRUE(f.converged);
  EXPECT_LE(calls, 3);
  EXPECT_LT((f.on_axle - reference.on_axle).norm(), 1e-6);
}

}  // namespace
