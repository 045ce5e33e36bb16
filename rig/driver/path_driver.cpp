#include "rig/driver/path_driver.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace rig::driver {

using model::Signal;

io::InputSet path_driver_inputs() {
  io::InputSet inputs;
  for (const Signal s :
       {Signal::kSteeringWheelAngleCmd, Signal::kThrottlePedal, Signal::kBrakePressureFront,
        Signal::kBrakePressureRear, Signal::kGearRequest})
    inputs.set(model::index(s));
  return inputs;
}

std::vector<PathPoint> iso3888_1_centreline(double start_x_m, double lane_offset_m) {
  // section lengths: 1 lane 15 m, 2 change 30 m, 3 offset lane 25 m, 4 change 25 m, 5 lane 15 m
  std::vector<PathPoint> path;
  const auto change = [&](double x0, double len, double y0, double y1) {
    for (int k = 0; k <= 30; ++k) {
      const double u = k / 30.0;
      path.push_back({start_x_m + x0 + u * len, y0 + (y1 - y0) * 0.5 * (1 - std::cos(M_PI * u))});
    }
  };
  path.push_back({start_x_m - 200, 0});
  change(15, 30, 0, lane_offset_m);
  change(70, 25, lane_offset_m, 0);
  path.push_back({start_x_m + 300, 0});
  return path;
}

PathDriverParams read_path_driver(io::config::StrictTable& t, const PathDriverVehicle& vehicle) {
  PathDriverParams p;
  const std::string path = t.choice("path", "iso3888-1", {"iso3888-1", "straight"});
  const double start_x_m = t.number_in("path_start_x_m", 30.0, -1e6, 1e6);
  const double lane_offset_m = t.number_in("lane_offset_m", 3.5, -20.0, 20.0);
  if (path == "iso3888-1") {
    p.path = iso3888_1_centreline(start_x_m, lane_offset_m);
  } else {
    p.path = {{start_x_m - 1e6, 0.0}, {start_x_m + 1e6, 0.0}};
  }
  p.target_speed_mps = t.number_in("target_speed_mps", p.target_speed_mps, 0.0, 100.0);
  p.preview_time_s = t.number_in("preview_time_s", p.preview_time_s, 0.05, 10.0);
  p.preview_min_m = t.number_in("preview_min_m", p.preview_min_m, 0.5, 100.0);
  p.wheelbase_m = t.number_in("wheelbase_m", vehicle.wheelbase_m, 0.5, 20.0);
  p.steering_ratio = t.number_in("steering_ratio", vehicle.steering_ratio, 1.0, 100.0);
  p.max_steering_wheel_rad =
      t.number_in("max_steering_wheel_rad", p.max_steering_wheel_rad, 0.1, 50.0);
  p.speed_gain_per_mps = t.number_in("speed_gain_per_mps", p.speed_gain_per_mps, 0.0, 10.0);
  p.speed_integral_per_m = t.number_in("speed_integral_per_m", p.speed_integral_per_m, 0.0, 10.0);
  p.brake_gain_pa_per_mps = t.number_in("brake_gain_pa_per_mps", p.brake_gain_pa_per_mps, 0.0, 1e8);
  if (t.has("stop_time_s")) p.stop_time_s = t.number_in("stop_time_s", 0.0, 1e9);
  p.stop_brake_pressure_front_pa =
      t.number_in("stop_brake_pressure_front_pa", p.stop_brake_pressure_front_pa, 0.0, 3e7);
  p.stop_brake_pressure_rear_pa =
      t.number_in("stop_brake_pressure_rear_pa", p.stop_brake_pressure_rear_pa, 0.0, 3e7);
  p.stop_brake_ramp_s = t.number_in("stop_brake_ramp_s", p.stop_brake_ramp_s, 0.0, 100.0);
  t.finish();
  return p;
}

PathDriver::PathDriver(PathDriverParams params, const io::InputSet& feeds)
    : Driver(feeds), p_(std::move(params)) {}

double PathDriver::path_y(double x) const noexcept {
  const auto& path = p_.path;
  if (path.empty()) return 0;
  if (x <= path.front().x_m) return path.front().y_m;
  if (x >= path.back().x_m) return path.back().y_m;
  const auto it = std::lower_bound(path.begin(), path.end(), x,
                                   [](const PathPoint& p, double v) { return p.x_m < v; });
  const PathPoint& b = *it;
  const PathPoint& a = *(it - 1);
  return a.y_m + (b.y_m - a.y_m) * (x - a.x_m) / (b.x_m - a.x_m);
}

void PathDriver::update(double t, model::Signals& s) noexcept {
  const double dt = std::clamp(t - last_time_s_, 0.0, 0.1);
  last_time_s_ = t;
  const double v = s[Signal::kVehicleSpeed];
  const double x = s[Signal::kPositionX], y = s[Signal::kPositionY], psi = s[Signal::kHeading];
  lateral_offset_m_ = y - path_y(x);
  // speed: PI on throttle, P on brake pressure
  const double err = p_.target_speed_mps - v;
  double throttle = 0, brake_front = 0, brake_rear = 0;
  if (t >= p_.stop_time_s) {  // stop phase: no throttle, circuit pressures ramped and held
    const double ramp =
        p_.stop_brake_ramp_s > 0 ? std::min(1.0, (t - p_.stop_time_s) / p_.stop_brake_ramp_s) : 1.0;
    brake_front = ramp * p_.stop_brake_pressure_front_pa;
    brake_rear = ramp * p_.stop_brake_pressure_rear_pa;
  } else {
    integral_ = std::clamp(integral_ + err * dt, -20.0, 20.0);
    throttle =
        std::clamp(p_.speed_gain_per_mps * err + p_.speed_integral_per_m * integral_, 0.0, 1.0);
    brake_front = err < -1.0 ? p_.brake_gain_pa_per_mps * (-err - 1.0) : 0.0;
    brake_rear = 0.5 * brake_front;
  }
  if (feeds(Signal::kThrottlePedal)) s.set(Signal::kThrottlePedal, throttle);
  if (feeds(Signal::kBrakePressureFront)) s.set(Signal::kBrakePressureFront, brake_front);
  if (feeds(Signal::kBrakePressureRear)) s.set(Signal::kBrakePressureRear, brake_rear);
  if (feeds(Signal::kGearRequest)) s.set(Signal::kGearRequest, 99);
  // steering: pure pursuit towards the path point one preview distance ahead
  const double look = std::max(p_.preview_min_m, std::abs(v) * p_.preview_time_s);
  const double cx = std::cos(psi), sx = std::sin(psi);
  const double tx = x + look * cx;
  const double ty = path_y(tx);
  const double lateral = -(tx - x) * sx + (ty - y) * cx;  // target in vehicle axes
  const double wheel = std::atan(2.0 * p_.wheelbase_m * lateral / (look * look));
  const double sw =
      std::clamp(p_.steering_ratio * wheel, -p_.max_steering_wheel_rad, p_.max_steering_wheel_rad);
  if (feeds(Signal::kSteeringWheelAngleCmd)) s.set(Signal::kSteeringWheelAngleCmd, sw);
}

}  // namespace rig::driver
