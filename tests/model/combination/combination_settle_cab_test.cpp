// A combination settled at speed starts as level as its tractor alone (issue 17, stop 28's bug:
// the 40 t tractor-semitrailer with the cab tractor settled at 50 km/h started rolled
// 0.016 rad, the cab thrown 60 mm sideways onto its lateral stops by the first step). Reference:
// the same tractor settled alone at the same speed (VehicleModel::settle): straight ahead on a
// flat road both are symmetric, so the tractor's roll and the cab's lateral offset after settle
// and over the first 100 ms must stay within what the single vehicle shows (a few 1e-4 rad and
// 1e-4 m) - a fraction of the cab's lateral clearance, never on its stops.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/combination/combination.h"
#include "model/vehicle/free_body/free_bodies.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/combination_files.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::combination {
namespace {

constexpr double kSpeedMps = 13.89;  // 50 km/h, the combinations' initial_speed_mps
constexpr int kFirstSteps = 100;     // the first 100 ms at h = 1 ms

/// The largest |roll| of the tractor and |lateral offset| of its cab (free body 0, relative to
/// the chassis at its design position) over the state after settle and the first 100 ms.
struct Start {
  double roll_rad = 0, cab_y_m = 0;
  bool cab_on_stop = false;
};

void take(const vehicle::VehicleModel& tractor, Start& s) {
  const vehicle::VehicleParams& p = tractor.params();
  s.roll_rad = std::max(s.roll_rad, std::abs(tractor.state().framework_y(5)));
  const vehicle::RelativeMotion m = vehicle::free_body_motion(p.free_bodies[0], 0, tractor.state());
  s.cab_y_m = std::max(s.cab_y_m, std::abs(m.position_m.y()));
  s.cab_on_stop =
      s.cab_on_stop || vehicle::free_body_beyond_stop_m(p.free_bodies[0], 0, tractor.state()) > 0;
}

template <class Model>
Start first_steps(Model& m, const vehicle::VehicleModel& tractor, Signals s) {
  Start st;
  take(tractor, st);
  for (int k = 0; k < kFirstSteps; ++k) {
    EXPECT_EQ(m.step(s), StepStatus::kOk);
    take(tractor, st);
  }
  return st;
}

Signals rolling_inputs(double throttle) {
  Signals s = test::all_driver_inputs();
  s[Signal::kGearRequest] = 99;
  s[Signal::kThrottlePedal] = throttle;
  return s;
}

Start alone(const vehicle::VehicleParams& p) {
  vehicle::VehicleModel v(p, 1e-3);
  const vehicle::Equilibrium e = v.settle(kSpeedMps);
  return first_steps(v, v, rolling_inputs(e.throttle));
}

Start combined(const CombinationParams& p) {
  Combination c(p, 1e-3);
  const vehicle::Equilibrium e = c.settle(kSpeedMps);
  return first_steps(c, c.unit(0), rolling_inputs(e.throttle));
}

void expect_as_alone(const CombinationParams& p, const char* what) {
  const Start a = alone(p.units[0]);
  const Start c = combined(p);
  std::printf(
      "%s at %.2f m/s, settle + 100 ms: tractor |roll| %.2e rad (alone %.2e), cab |y| "
      "%.2e m (alone %.2e), cab on its stops %d (alone %d)\n",
      what, kSpeedMps, c.roll_rad, a.roll_rad, c.cab_y_m, a.cab_y_m, c.cab_on_stop, a.cab_on_stop);
  EXPECT_FALSE(a.cab_on_stop);
  EXPECT_FALSE(c.cab_on_stop) << what;
  // within what the tractor alone shows, with a margin for the semitrailer's own small asymmetry
  EXPECT_LT(c.roll_rad, 2 * a.roll_rad + 1e-4) << what;
  EXPECT_LT(c.cab_y_m, 2 * a.cab_y_m + 1e-4) << what;
}

TEST(CombinationSettle, FortyTonneStartsAsLevelAsItsTractorAlone) {
  expect_as_alone(test::load_combination(test::kTractorSemi40t), "tractor-semitrailer-40t");
}

TEST(CombinationSettle, CabTractorSemitrailerStartsAsLevelAsItsTractorAlone) {
  CombinationParams p = test::load_combination(test::kTractorSemi);
  p.units[0] =
      io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/tractor-6x4-cab.toml");
  expect_as_alone(p, "tractor-6x4-cab + semitrailer-3axle");
}

}  // namespace
}  // namespace rig::model::combination
