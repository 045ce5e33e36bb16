#include "rig/driver/path_driver.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rig::driver {

using model::Signal;
using model::SignalSource;

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

PathDriver::PathDriver(PathDriverParams params) : p_(std::move(params)) {}

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
  const auto mine = [&](Signal id) { return s.source[model::index(id)] == SignalSource::kDriver; };
  // speed: PI on throttle, P on brake pressure
  const double err = p_.target_speed_mps - v;
  integral_ = std::clamp(integral_ + err * dt, -20.0, 20.0);
  const double thr = p_.speed_gain_per_mps * err + p_.speed_integral_per_m * integral_;
  if (mine(Signal::kThrottlePedal)) s.set(Signal::kThrottlePedal, std::clamp(thr, 0.0, 1.0));
  const double brake = err < -1.0 ? p_.brake_gain_pa_per_mps * (-err - 1.0) : 0.0;
  if (mine(Signal::kBrakePressureFront)) s.set(Signal::kBrakePressureFront, brake);
  if (mine(Signal::kBrakePressureRear)) s.set(Signal::kBrakePressureRear, 0.5 * brake);
  if (mine(Signal::kGearRequest)) s.set(Signal::kGearRequest, 99);
  // steering: pure pursuit towards the path point one preview distance ahead
  const double look = std::max(p_.preview_min_m, std::abs(v) * p_.preview_time_s);
  const double cx = std::cos(psi), sx = std::sin(psi);
  const double tx = x + look * cx;
  const double ty = path_y(tx);
  const double lateral = -(tx - x) * sx + (ty - y) * cx;  // target in vehicle axes
  const double wheel = std::atan(2.0 * p_.wheelbase_m * lateral / (look * look));
  const double sw =
      std::clamp(p_.steering_ratio * wheel, -p_.max_steering_wheel_rad, p_.max_steering_wheel_rad);
  if (mine(Signal::kSteeringWheelAngleCmd)) s.set(Signal::kSteeringWheelAngleCmd, sw);
}

}  // namespace rig::driver
