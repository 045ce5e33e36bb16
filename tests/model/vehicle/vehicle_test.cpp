// Acceptance tests of the generic vehicle (issue 6) on the sedan of config/vehicles/sedan.toml.
#include <cmath>
#include <cstdio>
#include <functional>

#include <gtest/gtest.h>

#include "model/vehicle/vehicle_model.h"
#include "rig/vehicle_config/vehicle_config.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::vehicle {
namespace {

VehicleParams sedan() { return vehicle_config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml"); }

Signals driver_inputs() {
  Signals s;
  for (std::size_t i = 0; i < index(kFirstOutput); ++i) {
    s.valid[i] = true;
    s.source[i] = SignalSource::kDriver;
  }
  s[Signal::kGearRequest] = 99;
  return s;
}

/// Runs for `seconds`, calling `inputs(t, signals)` before each step; fails on a NaN.
void run(VehicleModel& m, Signals& s, double seconds, const std::function<void(double, Signals&)>& inputs) {
  const long n = std::lround(seconds / m.step_size_s());
  for (long k = 0; k < n; ++k) {
    if (inputs) inputs(m.time_s(), s);
    ASSERT_EQ(m.step(s), StepStatus::kOk) << "t = " << m.time_s();
  }
}

TEST(Vehicle, StaticEquilibrium) {
  const VehicleParams p = sedan();
  VehicleModel m(p, 1e-3);
  Signals s = driver_inputs();
  s[Signal::kGearRequest] = 0;
  run(m, s, 3.0, nullptr);
  double total = 0, front = 0;
  for (int i = 0; i < 4; ++i) total += m.wheel_load_n(i);
  front = m.wheel_load_n(0) + m.wheel_load_n(1);
  const double mass = m.framework().total_mass_kg();
  EXPECT_NEAR(total, mass * 9.81, 0.005 * mass * 9.81);
  // front share from the CG position (sprung mass at x = 0, unsprung masses at the axles)
  const double l = p.axles[0].position_x_m - p.axles[1].position_x_m;
  const double front_expected = p.chassis.mass_kg * 9.81 * (-p.axles[1].position_x_m) / l +
                                2 * p.axles[0].unsprung_mass_kg * 9.81;
  EXPECT_NEAR(front / total, front_expected / (mass * 9.81), 0.005 * front_expected / (mass * 9.81));
  std::printf("static: total %.1f N (m g %.1f N), front %.2f %% (CG %.2f %%)\n", total, mass * 9.81,
              100 * front / total, 100 * front_expected / (mass * 9.81));
}

}  // namespace
}  // namespace rig::model::vehicle
