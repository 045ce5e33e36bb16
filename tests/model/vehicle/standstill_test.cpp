// Stand-still and start-up (issue 12, part 4): the start in equilibrium (VehicleModel::settle)
// and the stop without rocking (model/tire's low-speed damping).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/report.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::vehicle {
namespace {

VehicleParams sedan() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
}

struct Extremes {
  double ax_dev = 0, az = 0;  // max |a_x - a_x,steady|, max |a_z|
};
/// Steps 1 s at the given inputs and returns the largest deviations from a_x = ax_steady, a_z = 0.
Extremes first_second(VehicleModel& m, Signals s, double ax_steady) {
  Extremes e;
  while (m.time_s() < 1.0 - 1e-9) {
    EXPECT_EQ(m.step(s), StepStatus::kOk);
    e.ax_dev = std::max(e.ax_dev, std::abs(m.state().acceleration_mps2.x() - ax_steady));
    e.az = std::max(e.az, std::abs(m.state().acceleration_mps2.z()));
  }
  return e;
}

// At rest with zero inputs: the static suspension and tire deflections from the start.
TEST(StartInEquilibrium, AtRestWithZeroInputs) {
  const VehicleParams p = sedan();
  Signals zero = test::all_driver_inputs();
  zero[Signal::kGearRequest] = 0;
  VehicleModel raw(p, 1e-3);  // the design position, as before
  const Extremes before = first_second(raw, zero, 0.0);
  VehicleModel m(p, 1e-3);
  const VehicleModel::Equilibrium e = m.settle(0.0);
  EXPECT_EQ(m.time_s(), 0.0);
  EXPECT_EQ(e.throttle, 0.0);
  const Extremes after = first_second(m, zero, 0.0);
  std::printf("at rest, first second: |a_x| %.4f, |a_z| %.4f m/s^2 (design position: %.3f, %.3f)\n",
              after.ax_dev, after.az, before.ax_dev, before.az);
  EXPECT_LT(after.ax_dev, 0.05);
  EXPECT_LT(after.az, 0.05);
}

// At 20 m/s with the throttle the settle reports: the steady rolling state from the start.
TEST(StartInEquilibrium, AtInitialSpeedWithTheHoldingThrottle) {
  const VehicleParams p = sedan();
  Signals s = test::all_driver_inputs();
  for (double v : {10.0, 20.0, 30.0}) {
    VehicleModel raw(p, 1e-3);
    raw.set_forward_speed(v);
    VehicleModel m(p, 1e-3);
    const VehicleModel::Equilibrium e = m.settle(v);
    s[Signal::kThrottlePedal] = e.throttle;
    const Extremes before = first_second(raw, s, e.residual_ax_mps2);
    const Extremes after = first_second(m, s, e.residual_ax_mps2);
    std::printf(
        "%.0f m/s: gear %d, throttle %.4f, residual a_x %.2e; first second |a_x - a_x,s| "
        "%.4f, |a_z| %.4f m/s^2 (not settled: %.3f, %.3f); v after 1 s %.4f m/s\n",
        v, e.gear, e.throttle, e.residual_ax_mps2, after.ax_dev, after.az, before.ax_dev, before.az,
        m.state().framework_z(0));
    EXPECT_GT(e.throttle, 0.0);
    EXPECT_LT(e.throttle, 1.0);
    EXPECT_LT(std::abs(e.residual_ax_mps2), 0.01);
    EXPECT_LT(after.ax_dev, 0.05);
    EXPECT_LT(after.az, 0.05);
    EXPECT_NEAR(m.state().framework_z(0), v, 0.05);
  }
}

struct StopFigures {
  double t_stop = -1;          // first v <= 0
  double max_ax_after_1s = 0;  // max |a_x| from t_stop + 1 s to the end of the hold
  double front_rolled_m = 0;   // the braked front wheels' rolled distance after the stop
  double body_back_m = 0;      // body travel back after the stop (largest)
  double body_settled_m = 0;   // ... and at the end of the hold
  /// the tires' elastic recovery: their mean deflection x_e from the stop to the end of the hold,
  /// and Newton's: at the stop the tire forces change by m a (a the deceleration just before),
  /// spread over four tires of stiffness c_x
  double tire_recovery_m = 0, tire_recovery_newton_m = 0;
  double pitch_change_rad = 0;  // pitch from the stop to the end of the hold (the dive recovers)
  long masked = 0, unmasked_at_rest = 0;
};
/// Braking from 8 m/s to stand-still (front 3 MPa, rear 1.5 MPa, in D) and holding 6 s.
StopFigures stop_and_hold(double grade) {
  VehicleParams p = sedan();
  p.road.grade = grade;
  VehicleModel m(p, 1e-3);
  m.settle(8.0);
  Signals s = test::all_driver_inputs();
  s[Signal::kBrakePressureFront] = 3e6;
  s[Signal::kBrakePressureRear] = 1.5e6;
  StopFigures f;
  double x_stop = 0, ax_before = 0, deflection_stop = 0, pitch_stop = 0;
  ModelReport report{};
  const auto mean_deflection_m = [&] {
    m.fill_report(report);
    double sum = 0;
    for (int i = 0; i < 4; ++i)
      sum += report.units[0].wheels[static_cast<std::size_t>(i)].deflection_x_m;
    return sum / 4;
  };
  while (m.time_s() < 8.0) {
    const double ax = m.state().acceleration_mps2.x();
    EXPECT_EQ(m.step(s), StepStatus::kOk);
    const double v = m.state().framework_z(0), x = m.state().framework_y(0);
    if (f.t_stop < 0 && v <= 0) {
      f.t_stop = m.time_s();
      x_stop = x;
      ax_before = ax;
      deflection_stop = mean_deflection_m();
      pitch_stop = report.units[0].orientation_rad[1];
    }
    if (f.t_stop < 0) continue;
    f.body_back_m = std::max(f.body_back_m, x_stop - x);
    f.body_settled_m = x_stop - x;
    for (int i : {0, 1})
      f.front_rolled_m +=
          std::abs(m.state().spin_radps[static_cast<std::size_t>(i)]) *
          m.workspace().wheels[static_cast<std::size_t>(i)].out.tire.rolling_radius_m * 1e-3;
    if (m.time_s() > f.t_stop + 1.0)
      f.max_ax_after_1s = std::max(f.max_ax_after_1s, std::abs(m.state().acceleration_mps2.x()));
    m.fill_report(report);
    for (int i = 0; i < 4; ++i) {
      const WheelReport& w = report.units[0].wheels[static_cast<std::size_t>(i)];
      f.masked += w.slip_valid == 0 ? 1 : 0;
      f.unmasked_at_rest += (m.time_s() > f.t_stop + 1.0 && w.slip_valid != 0) ? 1 : 0;
    }
  }
  f.tire_recovery_m = mean_deflection_m() - deflection_stop;  // x_e grows as the hub moves back
  f.pitch_change_rad = report.units[0].orientation_rad[1] - pitch_stop;
  double load_n = 0;
  for (int i = 0; i < 4; ++i) load_n += report.units[0].wheels[static_cast<std::size_t>(i)].load_n;
  const double mass_kg = load_n * std::sqrt(1 + grade * grade) / 9.81;  // F_z sum = m g cos
  f.tire_recovery_newton_m =
      mass_kg * std::abs(ax_before) / (4 * p.axles[0].tire.tmeasy.longitudinal_stiffness_npm);
  std::printf(
      "grade %.0f %%: stop at %.3f s; |a_x| after 1 s <= %.4f m/s^2; front wheels rolled "
      "%.3f mm; body back %.1f mm (settled %.1f mm) = tires' elastic recovery %.1f mm (Newton: "
      "m |a| / (4 c_x) = %.0f kg %.2f m/s^2 -> %.1f mm) + pitch %.4f rad\n",
      100 * grade, f.t_stop, f.max_ax_after_1s, 1e3 * f.front_rolled_m, 1e3 * f.body_back_m,
      1e3 * f.body_settled_m, 1e3 * f.tire_recovery_m, mass_kg, std::abs(ax_before),
      1e3 * f.tire_recovery_newton_m, f.pitch_change_rad);
  return f;
}

// After a stop the car stands still: no rocking on its tire springs (the low-speed damping of
// model/tire), |a_x| < 0.2 m/s^2 from 1 s after stand-still; the car does not roll back: the
// braked wheels turn less than 0.1 mm (the roll-back a wheel-speed sensor or a hill-hold ECU
// sees; the limit of issue 12 is 2 mm); the slips are flagged invalid at rest. The body's
// travel back after the stop is elastic: the tires' deflection recovers by Newton's m a /
// (4 c_x) (braking force to holding force) and the brake dive's pitch recovers; it settles, it
// does not creep.
TEST(StandStill, NoRockingAfterTheStopOnTheFlatAndOnTheGrade) {
  for (double grade : {0.0, 0.2}) {
    const StopFigures f = stop_and_hold(grade);
    ASSERT_GT(f.t_stop, 0.0);
    EXPECT_LT(f.max_ax_after_1s, 0.2);
    EXPECT_LT(f.front_rolled_m, 1e-4);
    EXPECT_LT(f.body_back_m - f.body_settled_m, 0.005);  // at most a damped overshoot
    EXPECT_NEAR(f.tire_recovery_m, f.tire_recovery_newton_m, 0.1 * f.tire_recovery_newton_m);
    EXPECT_GT(f.masked, 0);
    EXPECT_EQ(f.unmasked_at_rest, 0);
  }
}

}  // namespace
}  // namespace rig::model::vehicle
