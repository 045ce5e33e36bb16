// Closed-loop runs of the sedan with the rig's path driver (rig/driver): the ISO 3888-1 double
// lane change at 60 km/h stays inside the lanes at h = 1 and 2 ms.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/vehicle/vehicle_model.h"
#include "rig/driver/path_driver.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::vehicle {
namespace {

VehicleParams sedan() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
}

Signals driver_inputs() { return test::all_driver_inputs(); }

TEST(Vehicle, DoubleLaneChangeClosedLoopAt60kmh) {
  for (double h : {1e-3, 2e-3}) {
    const VehicleParams p = sedan();
    VehicleModel m(p, h);
    m.set_forward_speed(60 / 3.6);
    driver::PathDriverParams dp;
    dp.path = driver::iso3888_1_centreline(30.0);
    dp.wheelbase_m = p.axles[0].position_x_m - p.axles[1].position_x_m;
    dp.steering_ratio = p.steering.steering_arm_m / p.steering.rack_per_pinion_m_per_rad;
    driver::PathDriver d(dp);
    Signals s = driver_inputs();
    double max_lane = 0, max_offset_lane1 = 0, max_offset_lane3 = 0, max_offset_lane5 = 0,
           max_ay = 0;
    const long n = std::lround(12.0 / h);
    for (long k = 0; k < n; ++k) {
      d.update(m.time_s(), s);
      ASSERT_EQ(m.step(s), StepStatus::kOk);
      const double x = s[Signal::kPositionX] - 30.0, off = std::abs(d.lateral_offset_m());
      if (x >= 0 && x <= 15) max_offset_lane1 = std::max(max_offset_lane1, off);
      if (x >= 45 && x <= 70) max_offset_lane3 = std::max(max_offset_lane3, off);
      if (x >= 95 && x <= 110) max_offset_lane5 = std::max(max_offset_lane5, off);
      if (x >= 0 && x <= 125) max_ay = std::max(max_ay, std::abs(s[Signal::kLateralAccel]));
      max_lane = std::max(max_lane, off);
    }
    std::printf(
        "DLC 60 km/h h=%.0f ms: max |offset| lane 1 %.3f m, lane 3 %.3f m, lane 5 %.3f m, max "
        "|a_y| %.2f "
        "m/s^2, speed at end %.1f km/h\n",
        h * 1e3, max_offset_lane1, max_offset_lane3, max_offset_lane5, max_ay,
        3.6 * s[Signal::kVehicleSpeed]);
    // ISO 3888-1 lane half-widths minus half the car width (1.80 m): 0.21, 0.30, 0.39 m
    EXPECT_LT(max_offset_lane1, 0.21);
    EXPECT_LT(max_offset_lane3, 0.30);
    EXPECT_LT(max_offset_lane5, 0.39);
  }
}

}  // namespace
}  // namespace rig::model::vehicle
