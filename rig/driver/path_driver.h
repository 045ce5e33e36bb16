#pragma once
/// @file
/// A closed-loop driver: a PI speed controller (throttle / brake pressure) plus a preview
/// (pure-pursuit) path follower on the steering wheel angle. Writes only the inputs it was
/// handed (path_driver_inputs() unless routed elsewhere). Built at load time; update() never
/// allocates.
///
/// Optional stop phase (the demo's brake-and-hold): from stop_time_s on the throttle is 0 and the
/// brake circuit pressures ramp linearly to stop_brake_pressure_{front,rear}_pa over
/// stop_brake_ramp_s and are held there, whatever the speed (dry friction holds the car).

#include <limits>
#include <vector>

#include "io/config/strict_table.h"
#include "rig/driver/driver.h"

namespace rig::driver {

struct PathPoint {
  double x_m = 0;
  double y_m = 0;
};

struct PathDriverParams {
  std::vector<PathPoint> path;  ///< centreline in the road frame, x increasing
  /// > 0: the path is instead a circle of this radius, driven counter-clockwise (to the left),
  /// centred at circle_centre (ISO 4138 constant radius) [m].
  double circle_radius_m = 0;
  PathPoint circle_centre{};
  double target_speed_mps = 60 / 3.6;
  /// Speed steps (ISO 4138 steady states): the target rises by speed_step_mps every
  /// speed_step_duration_s, up to target_speed_max_mps; 0: a constant target.
  double speed_step_mps = 0;
  double speed_step_duration_s = 5.0;
  double target_speed_max_mps = 100.0;
  double gear_request = 99;     ///< sent as the gear request (99: automatic; n: hold gear n)
  double preview_time_s = 0.9;  ///< look-ahead distance = max(min, v T)
  double preview_min_m = 6.0;
  /// Integral action on the lateral offset (holds the circle's radius against the body slip
  /// angle that pure pursuit on the heading leaves): road-wheel steer per m s of offset; 0: none.
  double offset_integral_radpms = 0;
  double wheelbase_m = 2.8;
  double steering_ratio = 16.0;  ///< steering wheel angle / road wheel angle
  double max_steering_wheel_rad = 8.0;
  double speed_gain_per_mps = 0.3;     ///< throttle per m/s of speed error
  double speed_integral_per_m = 0.05;  ///< throttle per m of integrated speed error
  double brake_gain_pa_per_mps = 1.5e6;
  /// Stop phase: start time [s] (infinity: none), circuit pressures [Pa], ramp time [s].
  double stop_time_s = std::numeric_limits<double>::infinity();
  double stop_brake_pressure_front_pa = 3.0e6;
  double stop_brake_pressure_rear_pa = 1.5e6;
  double stop_brake_ramp_s = 0.5;
};

/// Vehicle geometry the path driver's pure pursuit needs (defaults for read_path_driver).
struct PathDriverVehicle {
  double wheelbase_m = 2.8;      ///< steered axle to the mean of the unsteered axles
  double steering_ratio = 16.0;  ///< steering wheel angle / road wheel angle
};

/// Reads `[driver] kind = "path"` (the caller has read `kind`):
///   path = "iso3888-1" | "straight" | "circle", path_start_x_m, lane_offset_m (ISO 3888-1
///   centreline), circle_radius_m (circle: tangent to the x axis at path_start_x_m, to the left),
///   target_speed_mps, speed_step_mps, speed_step_duration_s, target_speed_max_mps, gear_request,
///   offset_integral_radpms,
///   preview_time_s, preview_min_m, wheelbase_m and steering_ratio (default: `vehicle`),
///   max_steering_wheel_rad, speed_gain_per_mps, speed_integral_per_m, brake_gain_pa_per_mps,
///   stop_time_s, stop_brake_pressure_front_pa, stop_brake_pressure_rear_pa, stop_brake_ramp_s.
/// Throws ConfigError(file:line) on unknown keys or impossible values; calls finish().
PathDriverParams read_path_driver(io::config::StrictTable& driver_table,
                                  const PathDriverVehicle& vehicle);

/// ISO 3888-1 double lane change centreline (sections 15 / 30 / 25 / 25 / 15 m + run-out),
/// lane offset 3.5 m, smooth (cosine) transitions; starts at x = start_x_m.
std::vector<PathPoint> iso3888_1_centreline(double start_x_m, double lane_offset_m = 3.5);

/// What a path driver can write: the steering wheel angle, throttle, both brake circuits and
/// the gear request.
io::InputSet path_driver_inputs();

class PathDriver final : public Driver {
 public:
  /// `feeds`: the inputs it writes (default: all it can).
  explicit PathDriver(PathDriverParams params, const io::InputSet& feeds = path_driver_inputs());
  void update(double sim_time_s, model::Signals& signals) noexcept override;
  /// Lateral offset of the vehicle CG from the path at its x (last update) [m].
  [[nodiscard]] double lateral_offset_m() const noexcept { return lateral_offset_m_; }
  /// Path y at road x (linear between points; clamped at the ends).
  [[nodiscard]] double path_y(double x_m) const noexcept;
  /// The speed target at a time (the steps included) [m/s].
  [[nodiscard]] double target_speed_mps(double sim_time_s) const noexcept;

 private:
  /// Road-frame point of the path one preview distance `look_m` ahead of (x, y, heading psi).
  [[nodiscard]] PathPoint preview_point(double x_m, double y_m, double psi_rad,
                                        double look_m) const noexcept;
  /// Lateral offset of (x, y) from the path: left of it + (on the circle: inside it) [m].
  [[nodiscard]] double offset_m(double x_m, double y_m) const noexcept;

  PathDriverParams p_;
  double integral_ = 0;
  double offset_integral_ms_ = 0;  ///< integral of the lateral offset [m s]
  double last_time_s_ = 0;
  double lateral_offset_m_ = 0;
};

}  // namespace rig::driver
