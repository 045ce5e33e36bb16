// Rack-in-the-loop (issue 15 item 6): the rack follows the measured travel and speed, the rig
// answers with the tie-rod forces; an invalid measurement holds the rack.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::vehicle {
namespace {

VehicleParams sedan(const char* file = "sedan.toml") {
  return io::config::load_vehicle_file(std::string(RIG_SOURCE_DIR "/config/vehicles/") + file);
}

/// One step of the built-in (column) sedan's step steer at 80 km/h: what a bench would measure
/// (rack travel at the step's start, rack speed at its end: the implicit step's y+ = y + h z+)
/// and what the vehicle did.
struct Sample {
  double rack_start_m, rack_speed_end_mps, rack_end_m, yaw_rate_radps, left_n, right_n;
};

constexpr double kH = 1e-3;
constexpr double kSpeedMps = 80 / 3.6;

double throttle(const Signals& s) {
  return std::clamp(0.2 + 0.5 * (kSpeedMps - s[Signal::kVehicleSpeed]), 0.0, 1.0);
}

std::vector<Sample> column_step_steer(double seconds) {
  VehicleModel m(sedan(), kH);
  Signals s = test::all_driver_inputs();
  m.set_forward_speed(kSpeedMps);
  std::vector<Sample> out;
  ModelReport report;
  for (long k = 0; k < std::lround(seconds / kH); ++k) {
    const double t = m.time_s();
    s[Signal::kSteeringWheelAngleCmd] = 0.5 * std::clamp((t - 0.5) / 0.1, 0.0, 1.0);
    s[Signal::kThrottlePedal] = throttle(s);
    Sample x{};
    x.rack_start_m = m.state().steering_y(1);
    if (m.step(s) != StepStatus::kOk) throw std::runtime_error("column step failed");
    x.rack_speed_end_mps = m.state().steering_z(1);
    x.rack_end_m = m.state().steering_y(1);
    x.yaw_rate_radps = s[Signal::kYawRate];
    m.fill_report(report);
    x.left_n = report.steering.tie_rod_force_left_n;
    x.right_n = report.steering.tie_rod_force_right_n;
    out.push_back(x);
  }
  return out;
}

TEST(RackInTheLoop, ConfigSelectsIt) {
  EXPECT_EQ(sedan("sedan-rack-in-the-loop.toml").steering.system,
            SteeringSystemKind::kRackInTheLoop);
  EXPECT_EQ(sedan().steering.system, SteeringSystemKind::kColumn);
}

// The bench replays the column model's rack: the rack-in-the-loop sedan must then be the same
// vehicle, step for step (its rack ends each step at u_m + h v_m, which is the column step's
// y+ = y + h z+), and send the same tie-rod forces.
TEST(RackInTheLoop, ReplayedRackReproducesTheBuiltInStepSteer) {
  const std::vector<Sample> ref = column_step_steer(3.0);
  VehicleModel m(sedan("sedan-rack-in-the-loop.toml"), kH);
  Signals s = test::all_driver_inputs();
  m.set_forward_speed(kSpeedMps);
  ModelReport report;
  double max_rack_err = 0, max_yaw_err = 0, max_force_err = 0, peak_force = 0;
  test::AllocationCounter counter;
  std::size_t allocations_before = 0;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    s[Signal::kThrottlePedal] = throttle(s);
    s.set(Signal::kRackPositionMeasured, ref[k].rack_start_m);
    s.set(Signal::kRackSpeedMeasured, ref[k].rack_speed_end_mps);
    if (k == 100) allocations_before = counter.count();
    Eigen::internal::set_is_malloc_allowed(k < 100 || k >= 200);  // steps 100..199: none
    ASSERT_EQ(m.step(s), StepStatus::kOk) << "k = " << k;
    if (k >= 100 && k < 200) {
      ASSERT_EQ(counter.count(), allocations_before) << "allocation in step " << k;
    }
    if (k < 200) continue;
    m.fill_report(report);
    const auto& st = report.steering;
    max_rack_err = std::max(max_rack_err, std::abs(m.state().steering_y(1) - ref[k].rack_end_m));
    max_yaw_err = std::max(max_yaw_err, std::abs(s[Signal::kYawRate] - ref[k].yaw_rate_radps));
    max_force_err = std::max({max_force_err, std::abs(st.tie_rod_force_left_n - ref[k].left_n),
                              std::abs(st.tie_rod_force_right_n - ref[k].right_n)});
    peak_force = std::max({peak_force, std::abs(ref[k].left_n), std::abs(ref[k].right_n)});
    // the steering wheel turns with the rack through the real gear
    EXPECT_NEAR(m.state().steering_y(0),
                m.state().steering_y(1) / m.params().steering.rack_per_pinion_m_per_rad, 1e-6);
  }
  Eigen::internal::set_is_malloc_allowed(true);
  const Sample& end = ref.back();
  std::printf(
      "replay: rack %.6f m, yaw rate %.5f rad/s, tie rods %.1f / %.1f N (peak %.1f N); max "
      "differences: rack %.2e m, yaw rate %.2e rad/s, tie-rod force %.2e N\n",
      end.rack_end_m, end.yaw_rate_radps, end.left_n, end.right_n, peak_force, max_rack_err,
      max_yaw_err, max_force_err);
  ASSERT_GT(end.yaw_rate_radps, 0.1);  // the maneuver steers (~0.3 rad/s)
  ASSERT_GT(peak_force, 100.0);        // and loads the tie rods
  EXPECT_LT(max_rack_err, 1e-9);
  EXPECT_LT(max_yaw_err, 1e-6 * end.yaw_rate_radps);
  EXPECT_LT(max_force_err, 1e-4 * peak_force);
}

// Measurement lost mid-maneuver: the rack holds the position the last valid step ended at, at
// rest; valid again, it follows the measurement at once.
TEST(RackInTheLoop, InvalidMeasurementHoldsTheLastPosition) {
  VehicleModel m(sedan("sedan-rack-in-the-loop.toml"), kH);
  Signals s = test::all_driver_inputs();
  m.set_forward_speed(kSpeedMps);
  const double u0 = 0.01, v0 = 0.02;  // a 10 mm rack travel, moving at 20 mm/s
  for (int k = 0; k < 200; ++k) {
    s[Signal::kThrottlePedal] = throttle(s);
    s.set(Signal::kRackPositionMeasured, u0);
    s.set(Signal::kRackSpeedMeasured, v0);
    ASSERT_EQ(m.step(s), StepStatus::kOk);
  }
  const double held = u0 + kH * v0;  // where the last valid step ended
  EXPECT_NEAR(m.state().steering_y(1), held, 1e-12);
  for (int k = 0; k < 300; ++k) {
    s[Signal::kThrottlePedal] = throttle(s);
    s.set(Signal::kRackPositionMeasured, 0.05, k % 2 == 0);  // invalid, or not finite
    s.set(Signal::kRackSpeedMeasured, k % 2 == 0 ? NAN : 1.0, true);
    ASSERT_EQ(m.step(s), StepStatus::kOk);
    ASSERT_NEAR(m.state().steering_y(1), held, 1e-12) << "k = " << k;
    ASSERT_NEAR(m.state().steering_z(1), 0.0, 1e-9);  // F h / m of the constraint's mass
  }
  s.set(Signal::kRackPositionMeasured, -0.004);
  s.set(Signal::kRackSpeedMeasured, 0.0);
  ASSERT_EQ(m.step(s), StepStatus::kOk);
  EXPECT_NEAR(m.state().steering_y(1), -0.004, 1e-12);
  std::printf("held at %.6f m through 300 invalid steps (yaw rate %.4f rad/s)\n", held,
              s[Signal::kYawRate]);
}

}  // namespace
}  // namespace rig::model::vehicle
