// Load-sharing bogies (issue 17 item 3, model/vehicle/load_sharing.h): a tridem's axle loads at
// rest, today +-15 % apart on independent springs, within 2 % of equal with connected air
// springs; a walking beam splits its load by the lever about its pivot; the rest of the vehicle
// sees the bogie as one spring at its load centre (lever rule).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/combination/combination.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/combination_files.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::vehicle {
namespace {

constexpr double kG = 9.81;

VehicleParams truck() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/truck-3axle.toml");
}

/// Axle loads after `seconds` at rest in neutral with the brakes on.
std::vector<double> loads_at_rest(const VehicleParams& p, double seconds) {
  VehicleModel m(p, 1e-3);
  Signals s = test::all_driver_inputs();
  s[Signal::kGearRequest] = 0;
  s[Signal::kBrakePressureFront] = 8e5;
  s[Signal::kBrakePressureRear] = 8e5;
  (void)m.settle(0.0, 0);
  const long n = std::lround(seconds / m.step_size_s());
  for (long k = 0; k < n; ++k) EXPECT_EQ(m.step(s), StepStatus::kOk);
  std::vector<double> loads;
  for (std::size_t a = 0; a < p.axles.size(); ++a)
    loads.push_back(m.wheel_load_n(static_cast<int>(2 * a)) +
                    m.wheel_load_n(static_cast<int>(2 * a + 1)));
  return loads;
}

/// The front axle and a two-axle bogie acting at x_g: the lever rule for the sprung mass, the
/// bogie's share split by w_1, w_2; plus each axle's unsprung weight.
std::vector<double> hand_loads(const VehicleParams& p, double x_g, double w1) {
  const double xf = p.axles[0].position_x_m, ms = p.chassis.mass_kg * kG;
  const double front = ms * (-x_g) / (xf - x_g), bogie = ms - front;
  const auto unsprung = [&](std::size_t a) { return 2 * p.axles[a].unsprung_mass_kg * kG; };
  return {front + unsprung(0), w1 * bogie + unsprung(1), (1 - w1) * bogie + unsprung(2)};
}

TEST(LoadSharing, AirSpringTandemCarriesEqualLoadsAndTheLeverRuleHolds) {
  VehicleParams p = truck();
  p.load_sharing.push_back({LoadSharingKind::kAirSprings, 1, 2, 0});
  const std::vector<double> loads = loads_at_rest(p, 1.0);
  const double x_g = 0.5 * (p.axles[1].position_x_m + p.axles[2].position_x_m);
  const std::vector<double> hand = hand_loads(p, x_g, 0.5);
  for (std::size_t a = 0; a < 3; ++a) {
    std::printf("air tandem: axle %zu %.1f N, hand %.1f N (%.4f %%)\n", a + 1, loads[a], hand[a],
                100 * (loads[a] / hand[a] - 1));
    EXPECT_NEAR(loads[a], hand[a], 1e-3 * hand[a]);
  }
}

TEST(LoadSharing, WalkingBeamSplitsByItsLever) {
  VehicleParams p = truck();
  const double x1 = p.axles[1].position_x_m, x2 = p.axles[2].position_x_m;
  const double pivot = x2 + 0.6 * (x1 - x2);  // nearer the front axle: it carries 60 %
  p.load_sharing.push_back({LoadSharingKind::kWalkingBeam, 1, 2, pivot});
  const std::vector<double> loads = loads_at_rest(p, 1.0);
  const double w1 = (pivot - x2) / (x1 - x2);
  const std::vector<double> hand = hand_loads(p, w1 * x1 + (1 - w1) * x2, w1);
  for (std::size_t a = 0; a < 3; ++a) {
    std::printf("walking beam (pivot %.3f m): axle %zu %.1f N, hand %.1f N (%.4f %%)\n", pivot,
                a + 1, loads[a], hand[a], 100 * (loads[a] / hand[a] - 1));
    EXPECT_NEAR(loads[a], hand[a], 1e-3 * hand[a]);
  }
}

TEST(LoadSharing, BogiesRunAStepSteerAtOneMillisecond) {
  for (const LoadSharingParams& g :
       {LoadSharingParams{LoadSharingKind::kAirSprings, 1, 2, 0},
        LoadSharingParams{LoadSharingKind::kWalkingBeam, 1, 2, -1.27}}) {
    VehicleParams p = truck();
    p.load_sharing.push_back(g);
    VehicleModel m(p, 1e-3);
    Signals s = test::all_driver_inputs();
    m.set_forward_speed(16.67);
    s[Signal::kThrottlePedal] = 0.3;
    double late_min = 1e9, late_max = -1e9;
    for (int k = 0; k < 5000; ++k) {
      s[Signal::kSteeringWheelAngleCmd] = k < 500 ? 0.0 : 0.8;
      ASSERT_EQ(m.step(s), StepStatus::kOk) << "t = " << m.time_s();
      if (k > 4000) {
        late_min = std::min(late_min, m.framework().coordinates()(8));  // axle 2 left hub
        late_max = std::max(late_max, m.framework().coordinates()(8));
      }
    }
    std::printf("%s: a_y %.2f m/s^2, axle 2 left hub %.5f..%.5f m\n",
                g.kind == LoadSharingKind::kAirSprings ? "air tandem" : "walking beam",
                m.state().acceleration_mps2.y(), late_min, late_max);
    EXPECT_GT(m.state().acceleration_mps2.y(), 1.0);
    EXPECT_LT(late_max - late_min, 2e-4);  // steady in the turn
  }
}

/// The semitrailer's tridem in the 40 t tractor-semitrailer at rest: largest deviation of its
/// three axle loads from their mean.
double tridem_spread(bool equalised) {
  combination::CombinationParams p = test::load_combination(test::kTractorSemi);
  if (equalised) p.units[1].load_sharing.push_back({LoadSharingKind::kAirSprings, 0, 3, 0});
  combination::Combination c(p, 1e-3);
  Signals s = test::all_driver_inputs();
  s[Signal::kGearRequest] = 0;
  s[Signal::kBrakePressureFront] = 8e5;
  s[Signal::kBrakePressureRear] = 8e5;
  for (int k = 0; k < 2000; ++k) EXPECT_EQ(c.step(s), StepStatus::kOk);
  std::vector<double> loads(3);
  for (int a = 0; a < 3; ++a)
    loads[static_cast<std::size_t>(a)] =
        c.unit(1).wheel_load_n(2 * a) + c.unit(1).wheel_load_n(2 * a + 1);
  const double mean = (loads[0] + loads[1] + loads[2]) / 3;
  double spread = 0;
  for (double l : loads) spread = std::max(spread, std::abs(l / mean - 1));
  std::printf("tridem %s: %.0f / %.0f / %.0f N, largest deviation from the mean %.2f %%\n",
              equalised ? "air springs connected" : "independent springs", loads[0], loads[1],
              loads[2], 100 * spread);
  return spread;
}

TEST(LoadSharing, TridemAxleLoadsAtRestWithinTwoPercentWhenEqualised) {
  EXPECT_GT(tridem_spread(false), 0.10);  // today: the springs' preloads alone
  EXPECT_LT(tridem_spread(true), 0.02);
}

TEST(LoadSharingConfig, BogiesLoadFromTheVehicleFile) {
  const VehicleParams p =
      io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/semitrailer-3axle-air.toml");
  ASSERT_EQ(p.load_sharing.size(), 1u);
  EXPECT_EQ(p.load_sharing[0].kind, LoadSharingKind::kAirSprings);
  EXPECT_EQ(p.load_sharing[0].first_axle, 0);
  EXPECT_EQ(p.load_sharing[0].axle_count, 3);
}

}  // namespace
}  // namespace rig::model::vehicle
