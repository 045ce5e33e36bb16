// The 40 t tractor-semitrailer (config/combinations/tractor-semitrailer-40t.toml, issue 17 item
// 7), its tractor on leaf-sprung rigid axles (config/vehicles/tractor-6x4-leaf.toml): gross
// combination mass, static axle and kingpin loads against the hand calculation, the
// equalised tridem and the tractor's leaf-balanced tandem; over a lane change and braking at h = 1
// ms at most 2 Newton iterations per coupled step (the joints) and no allocation.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "model/combination/combination.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/combination_files.h"
#include "tests/support/driver_inputs.h"
#include "tests/support/static_axle_loads.h"

namespace rig::model::combination {
namespace {

using test::kTractorSemi40t;

using vehicle::VehicleParams;

double unit_mass_kg(const VehicleParams& p) {
  double m = p.chassis.mass_kg;
  for (const auto& a : p.axles) m += 2 * a.unsprung_mass_kg;
  for (const auto& b : p.free_bodies) m += b.mass_kg;
  return m;
}

/// Axle a's vertical load on the road: its two wheels.
double axle_load_n(Combination& c, int unit, int axle) {
  return c.unit(unit).wheel_load_n(2 * axle) + c.unit(unit).wheel_load_n(2 * axle + 1);
}

/// The hand calculation: the semitrailer's tridem equalised (the lever rule between the kingpin
/// and the tridem centre on the sprung mass); the tractor's frame, rigid, on its steer axle and
/// its leaf-balanced tandem (the lever rule, the rocker's split) under the frame, the cab,
/// engine and seat and the kingpin load; each axle's load that and its unsprung weight. Returns
/// the axle loads of both units and the kingpin load.
struct HandLoads {
  std::array<double, 3> tractor_n{}, trailer_n{};
  double kingpin_n = 0;
};
HandLoads hand_loads(const CombinationParams& p) {
  const VehicleParams& t = p.units[0];
  const VehicleParams& s = p.units[1];
  const double g = t.road.gravity_mps2;
  HandLoads out;
  double x_tridem = 0;
  for (const auto& a : s.axles) x_tridem += a.position_x_m / 3;
  const double x_kingpin = p.joints[0].trailing_point_m.x();
  const double w_semi = s.chassis.mass_kg * g;
  out.kingpin_n = w_semi * (0 - x_tridem) / (x_kingpin - x_tridem);
  for (std::size_t a = 0; a < 3; ++a)
    out.trailer_n[a] = (w_semi - out.kingpin_n) / 3 + 2 * s.axles[a].unsprung_mass_kg * g;
  // tractor (tests/support/static_axle_loads.h): its frame on the steer axle's springs and the
  // leaf-balanced tandem under the frame, the cab, engine and seat and the kingpin load
  const std::array<double, 6> spring =
      test::static_spring_loads_n(t, out.kingpin_n, p.joints[0].leading_point_m.x());
  for (std::size_t a = 0; a < 3; ++a)
    out.tractor_n[a] = spring[a] + 2 * t.axles[a].unsprung_mass_kg * g;
  return out;
}

TEST(TractorSemitrailer40t, StaticAxleAndKingpinLoadsMatchTheHandCalculation) {
  const CombinationParams p = test::load_combination(kTractorSemi40t);
  ASSERT_EQ(p.units.size(), 2u);
  ASSERT_EQ(p.units[0].axles.size(), 3u);
  ASSERT_EQ(p.units[1].axles.size(), 3u);
  EXPECT_TRUE(p.units[0].frame.enabled);  // frame torsion (issue 17 item 7): loads unchanged by it
  const double gcm = unit_mass_kg(p.units[0]) + unit_mass_kg(p.units[1]);
  std::printf("gross combination mass %.1f kg (tractor %.1f kg)\n", gcm, unit_mass_kg(p.units[0]));
  EXPECT_NEAR(gcm, 40000.0, 1e-6);
  const HandLoads hand = hand_loads(p);
  Combination c(p, 1e-3);
  Signals s = test::all_driver_inputs();
  s[Signal::kGearRequest] = 0;
  // standing braked: unbraked, the combination creeps and its tires' rolling resistance reaches
  // the leaf-sprung tractor's axles as fore-aft housing loads, which the leaves' kinematics turn
  // into ~0.2 % of vertical load moved between the axles
  s[Signal::kBrakePressureFront] = 8e5;
  s[Signal::kBrakePressureRear] = 8e5;
  for (int k = 0; k < 3000; ++k) ASSERT_EQ(c.step(s), StepStatus::kOk);
  const double g = p.units[0].road.gravity_mps2;
  const double kingpin = -c.joint_force_n(0).z();
  std::printf("kingpin load %.1f N (hand %.1f N, %.2f t)\n", kingpin, hand.kingpin_n,
              hand.kingpin_n / g / 1000);
  EXPECT_NEAR(kingpin, hand.kingpin_n, 1e-3 * hand.kingpin_n);
  double total = 0;
  for (int u = 0; u < 2; ++u) {
    for (int a = 0; a < 3; ++a) {
      const double model = axle_load_n(c, u, a);
      const double expected =
          (u == 0 ? hand.tractor_n : hand.trailer_n)[static_cast<std::size_t>(a)];
      total += model;
      std::printf("%s axle %d: %.1f N = %.3f t (hand %.1f N, %+.4f %%)\n",
                  u == 0 ? "tractor" : "semitrailer", a + 1, model, model / g / 1000, expected,
                  100 * (model / expected - 1));
      EXPECT_NEAR(model, expected, 1e-3 * expected) << "unit " << u << " axle " << a + 1;
    }
  }
  EXPECT_NEAR(total, gcm * g, 1e-3 * gcm * g);  // the road carries the whole combination
  // the tridem's air springs equalise: each axle within 2 % of the mean
  const double mean = (axle_load_n(c, 1, 0) + axle_load_n(c, 1, 1) + axle_load_n(c, 1, 2)) / 3;
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(axle_load_n(c, 1, a), mean, 0.02 * mean) << "tridem axle " << a + 1;
  // and the tractor's leaf balance: its tandem axles within 2 % of each other (equal arms)
  EXPECT_NEAR(axle_load_n(c, 0, 2), axle_load_n(c, 0, 1), 0.02 * axle_load_n(c, 0, 1));
}

// A lane change at 50 km/h (one period of a 0.4 Hz steer, 1.2 rad at the wheel), then braking
// to stand-still; the joints' Newton converges in 1 or 2 iterations in every step, and the
// coupled step allocates nothing (malloc counter + EIGEN_RUNTIME_NO_MALLOC).
TEST(TractorSemitrailer40t, AtMostTwoNewtonIterationsAndNoAllocationPerStep) {
  Combination c(test::load_combination(kTractorSemi40t), 1e-3);
  c.set_forward_speed(13.89);
  Signals s = test::all_driver_inputs();
  const auto inputs = [](double t, Signals& sig) {
    const bool steering = t > 1.0 && t < 3.5;
    sig[Signal::kSteeringWheelAngleCmd] =
        steering ? 1.2 * std::sin(2 * std::numbers::pi * 0.4 * (t - 1.0)) : 0.0;
    sig[Signal::kThrottlePedal] = t < 6.0 ? 0.3 : 0.0;
    sig[Signal::kBrakePressureFront] = t > 6.0 ? 7e5 : 0.0;
    sig[Signal::kBrakePressureRear] = t > 6.0 ? 7e5 : 0.0;
  };
  for (int k = 0; k < 200; ++k) {  // lazy one-time initializations outside the counter
    inputs(c.time_s(), s);
    ASSERT_EQ(c.step(s), StepStatus::kOk);
  }
  std::array<int, 4> histogram{};  // iterations 0, 1, 2, more
  double max_yaw_rate = 0;
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  for (int k = 0; k < 13800; ++k) {
    inputs(c.time_s(), s);
    ASSERT_EQ(c.step(s), StepStatus::kOk);
    ++histogram[static_cast<std::size_t>(std::min(c.last_newton().iterations, 3))];
    max_yaw_rate = std::max(max_yaw_rate, std::abs(c.unit(0).speeds()(5)));
  }
  Eigen::internal::set_is_malloc_allowed(true);
  std::printf(
      "lane change + braking, 13 800 steps: Newton iterations 0: %d, 1: %d, 2: %d, more: %d; "
      "max yaw rate %.3f rad/s, end speed %.3f m/s, max |g| now %.2g m\n",
      histogram[0], histogram[1], histogram[2], histogram[3], max_yaw_rate, c.unit(0).speeds()(0),
      c.joint_violation_m(0));
  EXPECT_EQ(histogram[3], 0);
  EXPECT_GT(max_yaw_rate, 0.05);           // it did change lanes
  EXPECT_LT(c.unit(0).speeds()(0), 0.05);  // and stopped
  EXPECT_EQ(counter.count(), 0u);
}

}  // namespace
}  // namespace rig::model::combination
