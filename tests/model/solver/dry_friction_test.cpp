// Stick-predicted dry friction in the modified implicit Euler step (model/solver/dry_friction.h):
// a mass on dry friction under a ramped force against the analytic stick / slide / stop, and two
// friction elements coupled by a spring through M_VI, one hand-computed step per stick/slip set.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "model/solver/mechanical_stepper.h"

namespace rig::model::solver {
namespace {

/// A mass on a dry-friction guide, pushed by force_n (set before each step).
class SlidingMass final : public MechanicalBlock<1> {
 public:
  double mass_kg = 2.0, capacity_n = 10.0, force_n = 0.0;
  [[nodiscard]] Eigen::Index size() const noexcept override { return 1; }
  [[nodiscard]] Vector& coordinates() noexcept override { return y_; }
  [[nodiscard]] Vector& speeds() noexcept override { return z_; }
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override {
    (void)y;
    m(0, 0) = mass_kg;
  }
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override {
    (void)y;
    (void)z;
    q(0) = force_n;
  }
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override {
    (void)y;
    (void)z;
    dq_dy.setZero();
    dq_dz.setZero();
    return true;
  }
  void dry_friction(const Vector& y, const Vector& z,
                    FrictionSet<1>& contacts) const noexcept override {
    (void)y;
    (void)z;
    contacts.clear();
    contacts.add_on_coordinate(0, capacity_n);
  }

 private:
  Vector y_ = Vector::Constant(0.3), z_ = Vector::Zero();
};

// F(t) = k t up to t = 1 s, then held at 5 N; m = 2 kg, F_c = 10 N, k = 20 N/s.
// Analytic: sticks until t_1 = F_c / k = 0.5 s; slides with a = (F - F_c) / m, v(1 s) =
// k (1 - t_1)^2 / (2 m) = 1.25 m/s; then decelerates at (F_c - 5) / m = 2.5 m/s^2 and stops at
// t_s = 1 + 1.25 / 2.5 = 1.5 s; 5 N < F_c: sticks for good.
void ramp_case(double h) {
  SlidingMass b;
  MechanicalStepper<1> stepper(b);
  const double k = 20.0, t_s = 1.5, v_1 = 1.25;
  const double y0 = b.coordinates()(0);
  double t = 0.0, stop_t = -1.0, stop_y = 0.0, v_at_1 = -1.0;
  bool slid = false;
  const auto steps = static_cast<int>(std::lround(2.5 / h));
  for (int n = 0; n < steps; ++n, t = n * h) {
    b.force_n = t < 1.0 - 1e-12 ? k * t : 5.0;
    const double z_before = b.speeds()(0);
    Eigen::internal::set_is_malloc_allowed(false);
    stepper.advance(h);
    Eigen::internal::set_is_malloc_allowed(true);
    const double z = b.speeds()(0), t_end = t + h;
    ASSERT_GE(z, 0.0) << "no reversal (chatter) at t = " << t_end;
    if (b.force_n <= b.capacity_n && !slid) {  // before the break-away: exactly at rest
      ASSERT_EQ(z, 0.0) << t_end;
      ASSERT_EQ(b.coordinates()(0), y0) << t_end;
    }
    if (z > 0.0) {
      slid = true;
      // sliding: exactly the capacity against the motion, a = (F - F_c) / m
      ASSERT_NEAR((z - z_before) / h, (b.force_n - b.capacity_n) / b.mass_kg, 1e-9) << t_end;
    }
    if (std::abs(t_end - 1.0) < 0.5 * h) v_at_1 = z;
    if (slid && z == 0.0 && stop_t < 0) {
      stop_t = t_end;
      stop_y = b.coordinates()(0);
    }
    if (stop_t > 0) {  // stuck again for good: speed exactly 0, position unchanged
      ASSERT_EQ(z, 0.0) << t_end;
      ASSERT_EQ(b.coordinates()(0), stop_y) << t_end;
    }
  }
  std::printf("h = %.0f ms: v(1 s) %.5f m/s (analytic %.5f), stop at %.4f s (analytic %.4f)\n",
              h * 1e3, v_at_1, v_1, stop_t, t_s);
  EXPECT_TRUE(slid);
  EXPECT_NEAR(v_at_1, v_1, k / b.mass_kg * h);  // the explicit force sample: O(h)
  EXPECT_NEAR(stop_t, t_s, h + 1e-9);           // within one step (+ the time sum's rounding)
}

TEST(DryFriction, MassUnderRampedForceSticksSlidesStopsAt1ms) { ramp_case(1e-3); }
TEST(DryFriction, MassUnderRampedForceSticksSlidesStopsAt5ms) { ramp_case(5e-3); }

/// Two unit masses on dry friction joined by a spring k (the torsion bar between column and
/// rack), forces f1, f2; starts at rest with the spring relaxed.
class TwoElements final : public MechanicalBlock<2> {
 public:
  double k_npm = 100.0, f1 = 0, f2 = 0, c1 = 5.0, c2 = 5.0;
  [[nodiscard]] Eigen::Index size() const noexcept override { return 2; }
  [[nodiscard]] Vector& coordinates() noexcept override { return y_; }
  [[nodiscard]] Vector& speeds() noexcept override { return z_; }
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override {
    (void)y;
    m.setIdentity();
  }
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override {
    (void)z;
    const double spring = k_npm * (y(0) - y(1));
    q << f1 - spring, f2 + spring;
  }
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override {
    (void)y;
    (void)z;
    dq_dy << -k_npm, k_npm, k_npm, -k_npm;
    dq_dz.setZero();
    return true;
  }
  void dry_friction(const Vector& y, const Vector& z,
                    FrictionSet<2>& contacts) const noexcept override {
    (void)y;
    (void)z;
    contacts.clear();
    contacts.add_on_coordinate(0, c1);
    contacts.add_on_coordinate(1, c2);
  }

 private:
  Vector y_ = Vector::Zero(), z_ = Vector::Zero();
};

struct StepResult {
  Eigen::Vector2d z, lambda;
  FrictionState s1, s2;
};

StepResult one_step(double f1, double f2) {
  TwoElements b;
  b.f1 = f1;
  b.f2 = f2;
  MechanicalStepper<2> stepper(b);
  stepper.advance(0.01);
  const FrictionSolution& s = stepper.friction_solution();
  EXPECT_TRUE(s.exact);
  return {b.speeds(), {s.force[0], s.force[1]}, s.state[0], s.state[1]};
}

// h = 0.01 s, m = 1, k = 100: M_VI = [1 + h^2 k, -h^2 k; -h^2 k, 1 + h^2 k] = [1.01 -0.01; ..].
constexpr double kH = 0.01, kH2K = kH * kH * 100.0;

TEST(DryFriction, CoupledBothStick) {
  // from rest with both loads below capacity: lambda = -q, no motion
  const StepResult r = one_step(3.0, -2.0);
  EXPECT_EQ(r.s1, FrictionState::kStick);
  EXPECT_EQ(r.s2, FrictionState::kStick);
  EXPECT_EQ(r.z(0), 0.0);
  EXPECT_EQ(r.z(1), 0.0);
  EXPECT_NEAR(r.lambda(0), -3.0, 1e-12);
  EXPECT_NEAR(r.lambda(1), 2.0, 1e-12);
}

TEST(DryFriction, CoupledFirstSlidesSecondSticks) {
  // 1 slides at lambda_1 = -5: (1 + h^2 k) z1 / h = 8 - 5; z2 = 0 held by lambda_2 = -h k z1
  const StepResult r = one_step(8.0, 0.0);
  const double z1 = 3.0 * kH / (1 + kH2K);
  EXPECT_EQ(r.s1, FrictionState::kSlidePositive);
  EXPECT_EQ(r.s2, FrictionState::kStick);
  EXPECT_NEAR(r.z(0), z1, 1e-14);
  EXPECT_EQ(r.z(1), 0.0);
  EXPECT_NEAR(r.lambda(0), -5.0, 1e-12);
  EXPECT_NEAR(r.lambda(1), -kH2K / kH * z1, 1e-12);  // -0.0297 N: the spring's implicit pull
}

TEST(DryFriction, CoupledFirstSticksSecondSlides) {
  const StepResult r = one_step(0.0, -8.0);
  const double z2 = -3.0 * kH / (1 + kH2K);
  EXPECT_EQ(r.s1, FrictionState::kStick);
  EXPECT_EQ(r.s2, FrictionState::kSlideNegative);
  EXPECT_EQ(r.z(0), 0.0);
  EXPECT_NEAR(r.z(1), z2, 1e-14);
  EXPECT_NEAR(r.lambda(0), -kH2K / kH * z2, 1e-12);
  EXPECT_NEAR(r.lambda(1), 5.0, 1e-12);
}

TEST(DryFriction, CoupledBothSlide) {
  // net [3, -3] along M_VI's eigenvector [1, -1] (eigenvalue 1 + 2 h^2 k)
  const StepResult r = one_step(8.0, -8.0);
  const double z = 3.0 * kH / (1 + 2 * kH2K);
  EXPECT_EQ(r.s1, FrictionState::kSlidePositive);
  EXPECT_EQ(r.s2, FrictionState::kSlideNegative);
  EXPECT_NEAR(r.z(0), z, 1e-14);
  EXPECT_NEAR(r.z(1), -z, 1e-14);
  EXPECT_NEAR(r.lambda(0), -5.0, 1e-12);
  EXPECT_NEAR(r.lambda(1), 5.0, 1e-12);
}

TEST(DryFriction, CoupledSpringDragsTheStuckElementLoose) {
  // 2 is unloaded but the spring (implicit) pulls it: a stuck 2 would need lambda_2 = -h k z1
  // beyond a tiny capacity, so both slide: hand value from M_VI [z1; z2] / h = [8 - 5; -(-c2)]
  TwoElements b;
  b.f1 = 8.0;
  b.c2 = 0.01;
  MechanicalStepper<2> stepper(b);
  stepper.advance(kH);
  const Eigen::Matrix2d m_vi{{1 + kH2K, -kH2K}, {-kH2K, 1 + kH2K}};
  const Eigen::Vector2d z = kH * m_vi.inverse() * Eigen::Vector2d(3.0, -0.01);
  EXPECT_EQ(stepper.friction_solution().state[1], FrictionState::kSlidePositive);
  EXPECT_NEAR(b.speeds()(0), z(0), 1e-14);
  EXPECT_NEAR(b.speeds()(1), z(1), 1e-14);
  EXPECT_GT(b.speeds()(1), 0.0);
}

}  // namespace
}  // namespace rig::model::solver
