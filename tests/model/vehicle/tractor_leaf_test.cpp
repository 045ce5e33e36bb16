// The leaf-sprung 6x4 tractor (config/vehicles/tractor-6x4-leaf.toml, issue 17 item 7): three
// rigid axles on five-link leaf springs, the tandem on a leaf balance. Against independent
// numbers: the static axle loads of the hand calculation (a rigid frame on the steer axle and the
// balanced tandem, the lever rule and the rocker's split, with the cab, engine and seat on it),
// each leaf's vertical rate and static deflection at its design load against the FE beam
// (leaf_fe_reference.py, the numbers in the vehicle file's header), and while braking at
// h = 1 ms the leaves' Newton iterations within their limits and no allocation.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/vehicle/leaf_axle.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/driver_inputs.h"
#include "tests/support/static_axle_loads.h"
#include "tests/support/vehicle_rest.h"

namespace rig::model::vehicle {
namespace {

VehicleParams tractor() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/tractor-6x4-leaf.toml");
}

/// The hand calculation (tests/support/static_axle_loads.h): the frame, rigid, under its own
/// weight and the free bodies' on the steer axle's springs and the tandem's leaf balance (one
/// support, split by the rocker): the lever rule. Each leaf carries half its axle's spring load,
/// the road that and the axle's weight.
struct Hand {
  std::array<double, 3> leaf_n{}, axle_n{};
};
Hand hand_loads(const VehicleParams& p) {
  const std::array<double, 6> spring = test::static_spring_loads_n(p);
  Hand h;
  for (std::size_t a = 0; a < 3; ++a) {
    h.leaf_n[a] = 0.5 * spring[a];
    h.axle_n[a] = spring[a] + p.axles[a].rigid.mass_kg * p.road.gravity_mps2;
  }
  return h;
}

TEST(TractorLeaf, ThreeLeafAxlesCarryTheHandCalculationsStaticLoads) {
  const VehicleParams p = tractor();
  ASSERT_EQ(p.axles.size(), 3u);
  for (const AxleParams& a : p.axles) {
    EXPECT_EQ(a.kind, AxleKind::kRigid);
    EXPECT_TRUE(a.has_leaf_spring);
  }
  const Hand hand = hand_loads(p);
  VehicleModel m(p, 1e-3);
  Signals s = test::all_driver_inputs();
  test::rest(m, s, 1.0);
  const double g = p.road.gravity_mps2;
  // the tandem axles are held to 0.1 % of the tandem's load (the frame's settled pitch moves
  // ~15 N from the last axle to the first: the hand calculation ignores the free bodies'
  // heights over the frame; on a 16 kN tandem axle that is 0.1 % of its own load)
  const double tandem = hand.axle_n[1] + hand.axle_n[2];
  const double tandem_leaves = hand.leaf_n[1] + hand.leaf_n[2];
  for (std::size_t a = 0; a < 3; ++a) {
    const int w = 2 * static_cast<int>(a);
    const double load = m.wheel_load_n(w) + m.wheel_load_n(w + 1);
    std::printf("axle %zu: %.1f N = %.3f t (hand %.1f N, %+.4f %%)\n", a + 1, load, load / g / 1e3,
                hand.axle_n[a], 100 * (load / hand.axle_n[a] - 1));
    EXPECT_NEAR(load, hand.axle_n[a], 1e-3 * (a == 0 ? hand.axle_n[a] : tandem));
    const LeafAxleState& leaf = m.state().leaf_axles[a];
    ASSERT_EQ(leaf.axle, static_cast<int>(a));
    // the two sides differ by the seat's roll moment (it sits 0.5 m left): their mean
    const double mean = 0.5 * (leaf.spring_n[0] + leaf.spring_n[1]);
    std::printf("  leaves %.1f / %.1f N, mean %.1f (hand %.1f N)\n", leaf.spring_n[0],
                leaf.spring_n[1], mean, hand.leaf_n[a]);
    EXPECT_NEAR(mean, hand.leaf_n[a], 1e-3 * (a == 0 ? hand.leaf_n[0] : tandem_leaves));
  }
}

TEST(TractorLeaf, LeafRatesMatchTheFeBeamAtTheirDesignLoads) {
  const VehicleParams p = tractor();
  struct Case {
    int axle;
    double load_n, fe_rate_npm, fe_z_m;
  };
  const Case cases[] = {{0, 30000.0, 235907.0, 0.12637}, {1, 27000.0, 328970.0, 0.07580}};
  for (const Case& c : cases) {
    LeafAxleState slot;
    const LeafAxleSuspension e(c.axle, p.axles[static_cast<std::size_t>(c.axle)], c.load_n,
                               c.load_n, slot);
    AxleSuspensionForces up, down;
    e.forces_under_load(1e-3, 0, 0, 0, AxleHousingLoad{}, up);
    e.forces_under_load(-1e-3, 0, 0, 0, AxleHousingLoad{}, down);
    const double secant = -0.5 * (up.q(0) - down.q(0)) / 2e-3;
    std::printf(
        "axle %d leaf at %.0f N: rate %.0f N/m, FE %.0f (%+.2f %%); seat travel %.2f mm, "
        "FE %.2f mm\n",
        c.axle + 1, c.load_n, secant, c.fe_rate_npm, 100 * (secant / c.fe_rate_npm - 1),
        1e3 * e.rest_seat_z_m(0), 1e3 * c.fe_z_m);
    EXPECT_NEAR(secant, c.fe_rate_npm, 0.05 * c.fe_rate_npm);
    EXPECT_NEAR(e.rest_seat_z_m(0), c.fe_z_m, 0.02 * c.fe_z_m);
    // the file's spring_stiffness_npm (the static loads' weights) is this rate
    EXPECT_NEAR(p.axles[static_cast<std::size_t>(c.axle)].spring_stiffness_npm, c.fe_rate_npm,
                0.005 * c.fe_rate_npm);
  }
}

// Braking from 60 km/h at 3 bar (~0.3 g) to stand-still: every leaf's balance within its
// evaluation and Newton limits in every step, and no allocation (malloc counter +
// EIGEN_RUNTIME_NO_MALLOC).
TEST(TractorLeaf, BrakingKeepsTheLeavesNewtonInItsLimitsWithoutAllocation) {
  VehicleModel m(tractor(), 1e-3);
  Signals s = test::all_driver_inputs();
  (void)m.settle(16.67);
  s[Signal::kThrottlePedal] = 0.0;
  for (int k = 0; k < 500; ++k) ASSERT_EQ(m.step(s), StepStatus::kOk);  // warm, outside
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  int most_evaluations = 0, most_iterations = 0;
  double max_windup = 0;
  for (int k = 0; k < 5000; ++k) {
    const double ramp = std::min(1.0, k / 300.0);
    s[Signal::kBrakePressureFront] = 3e5 * ramp;
    s[Signal::kBrakePressureRear] = 3e5 * ramp;
    ASSERT_EQ(m.step(s), StepStatus::kOk) << "t = " << m.time_s();
    for (const LeafAxleState& l : m.state().leaf_axles) {
      if (l.axle < 0) continue;
      most_evaluations = std::max(most_evaluations, l.balance_evaluations);
      most_iterations = std::max({most_iterations, l.iterations[0], l.iterations[1]});
      max_windup = std::max(max_windup, l.pitch_rad - l.rest_pitch_rad);
    }
  }
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  ModelReport r;
  m.fill_report(r);
  std::printf("speed %.2f m/s; wind-up <= %.2f mrad; evaluations <= %d, iterations <= %d\n",
              r.units[0].velocity_mps[0], 1e3 * max_windup, most_evaluations, most_iterations);
  EXPECT_LT(r.units[0].velocity_mps[0], 16.0);  // it braked
  EXPECT_GT(max_windup, 1e-3);                  // the brake reaction winds the leaves up
  EXPECT_LE(most_evaluations, LeafAxleSuspension::kMaxBalanceEvaluations);
  EXPECT_LE(most_iterations, LeafAxleSuspension::kMaxBalanceEvaluations * 4);
}

}  // namespace
}  // namespace rig::model::vehicle
