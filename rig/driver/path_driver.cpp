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
  const std::string path = t.choice("path", "iso3888-1", {"iso3888-1", "straight", "circle"});
  const double start_x_m = t.number_in("path_start_x_m", 30.0, -1e6, 1e6);
  const double lane_offset_m = t.number_in("lane_offset_m", 3.5, -20.0, 20.0);
  if (path == "iso3888-1") {
    p.path = iso3888_1_centreline(start_x_m, lane_offset_m);
  } else {
    p.path = {{start_x_m - 1e6, 0.0}, {start_x_m + 1e6, 0.0}};
  }
  if (path == "circle") {
    p.circle_radius_m = t.number_in("circle_radius_m", 1.0, 1e4);
    p.circle_centre = {start_x_m, p.circle_radius_m};
  }
  p.target_speed_mps = t.number_in("target_speed_mps", p.target_speed_mps, 0.0, 100.0);
  p.speed_step_mps = t.number_in("speed_step_mps", 0.0, -10.0, 10.0);
  p.speed_step_duration_s = t.number_in("speed_step_duration_s", 5.0, 0.1, 1e4);
  p.target_speed_max_mps = t.number_in("target_speed_max_mps", 100.0, 0.0, 100.0);
  p.gear_request = static_cast<double>(t.integer_in("gear_request", 99, -1, 99));
  if (p.gear_request != std::round(p.gear_request))
    throw t.error("gear_request", "gear_request: need a whole gear number (99: automatic)");
  p.preview_time_s = t.number_in("preview_time_s", p.preview_time_s, 0.05, 10.0);
  p.preview_min_m = t.number_in("preview_min_m", p.preview_min_m, 0.5, 100.0);
  p.offset_integral_radpms = t.number_in("offset_integral_radpms", 0.0, 0.0, 1.0);
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

double PathDriver::target_speed_mps(double t) const noexcept {
  if (p_.speed_step_mps == 0) return p_.target_speed_mps;
  const double steps = std::floor(t / p_.speed_step_duration_s);
  return std::min(p_.target_speed_max_mps, p_.target_speed_mps + steps * p_.speed_step_mps);
}

PathPoint PathDriver::preview_point(double x, double y, double psi, double look) const noexcept {
  if (p_.circle_radius_m <= 0) {
    const double tx = x + look * std::cos(psi);
    return {tx, path_y(tx)};
  }
  // the circle's point an arc `look` ahead of the vehicle's projection (counter-clockwise)
  const PathPoint& c = p_.circle_centre;
  const double angle = std::atan2(y - c.y_m, x - c.x_m) + look / p_.circle_radius_m;
  return {c.x_m + p_.circle_radius_m * std::cos(angle),
          c.y_m + p_.circle_radius_m * std::sin(angle)};
}

double PathDriver::offset_m(double x, double y) const noexcept {
  if (p_.circle_radius_m <= 0) return y - path_y(x);
  return p_.circle_radius_m - std::hypot(x - p_.circle_centre.x_m, y - p_.circle_centre.y_m);
}

void PathDriver::update(double t, model::Signals& s) noexcept {
  const double dt = std::clamp(t - last_time_s_, 0.0, 0.1);
  last_time_s_ = t;
  const double v = s[Signal::kVehicleSpeed];
  const double x = s[Signal::kPositionX], y = s[Signal::kPositionY], psi = s[Signal::kHeading];
  lateral_offset_m_ = offset_m(x, y);
  // speed: PI on throttle, P on brake pressure
  const double err = target_speed_mps(t) - v;
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
  if (feeds(Signal::kGearRequest)) s.set(Signal::kGearRequest, p_.gear_request);
  // steering: pure pursuit towards the path point one preview distance ahead
  const double look = std::max(p_.preview_min_m, std::abs(v) * p_.preview_time_s);
  const double cx = std::cos(psi), sx = std::sin(psi);
  const PathPoint target = preview_point(x, y, psi, look);
  const double dx = target.x_m - x, dy = target.y_m - y;
  const double lateral = -dx * sx + dy * cx;  // in vehicle axes
  // pure pursuit's arc through the target: curvature 2 lateral / distance^2 (on the circle the
  // chord, shorter than the preview arc; ahead on a path the preview distance in x)
  const double distance2 = p_.circle_radius_m > 0 ? dx * dx + dy * dy : look * look;
  offset_integral_ms_ = std::clamp(offset_integral_ms_ + lateral_offset_m_ * dt, -50.0, 50.0);
  const double wheel = std::atan(2.0 * p_.wheelbase_m * lateral / distance2) -
                       p_.offset_integral_radpms * offset_integral_ms_;
  const double sw =
      std::clamp(p_.steering_ratio * wheel, -p_.max_steering_wheel_rad, p_.max_steering_wheel_rad);
  if (feeds(Signal::kSteeringWheelAngleCmd)) s.set(Signal::kSteeringWheelAngleCmd, sw);
}

}  // namespace rig::driver
