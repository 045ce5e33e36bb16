// The shipped ISO 4138 steady-state circle (config/maneuvers/circle-iso4138.toml): the sedan on
// R = 40 m, the path driver holding the radius and the speed in steps of 1 m/s. From the steady
// states it reports the understeer gradient, the steady maximum lateral acceleration and the
// rack force over a_y (the steering goes light near the limit: the tire's pneumatic trail).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "model/report.h"
#include "model/tire/tmeasy_tire.h"
#include "rig/config.h"
#include "rig/model_factory.h"
#include "tests/support/driver_inputs.h"

namespace rig {
namespace {

using model::Signal;

/// One steady state: the means over the last 3 s of a speed step.
struct SteadyPoint {
  double speed_mps = 0, target_mps = 0, lat_accel_mps2 = 0, radius_m = 0;
  double road_wheel_steer_rad = 0, steering_wheel_rad = 0, rack_force_n = 0;
  double lat_slip_inner = 0, lat_slip_outer = 0;  ///< front wheels' lateral slips
  std::array<double, 4> load_n{};                 ///< wheel loads: FL, FR, RL, RR
  std::array<double, 4> force_y_n{};              ///< lateral tire forces
  std::array<double, 4> steer_rad{};              ///< each wheel's steer angle
  /// speed constant within 0.1 m/s (near the target), mean radius within 3 % of the path's
  bool steady = false;
};

std::vector<SteadyPoint> run_circle(const RigConfig& c) {
  const auto model = make_model(c);
  const auto driver = make_driver(c);
  const driver::PathDriverParams& dp = *c.path_driver;
  const driver::PathDriver targets(dp);  // the speed schedule
  const double step_s = dp.speed_step_duration_s, h = c.rig.period_s;
  model::Signals s = test::all_driver_inputs();
  model::ModelReport report;
  std::vector<SteadyPoint> points;
  SteadyPoint sum;
  double v_min = 1e9, v_max = 0;
  int n = 0;
  const long steps = std::lround(c.rig.duration_s / h);
  for (long k = 0; k < steps; ++k) {
    const double t = model->time_s();
    driver->update(t, s);
    if (model->step(s) != model::StepStatus::kOk) break;
    const double phase = std::fmod(t + 0.5 * h, step_s);
    if (phase < step_s - 3.0) continue;
    model->fill_report(report);
    const auto& wheels = report.units[0].wheels;
    const double v = s[Signal::kVehicleSpeed], r = s[Signal::kYawRate];
    sum.speed_mps += v;
    sum.lat_accel_mps2 += v * r;  // steady state: a_y = v^2 / R = v r
    sum.radius_m += v / r;
    sum.road_wheel_steer_rad += 0.5 * (wheels[0].steer_angle_rad + wheels[1].steer_angle_rad);
    sum.steering_wheel_rad += s[Signal::kSteeringWheelAngle];
    sum.rack_force_n += std::abs(report.steering.rack_force_n);
    sum.lat_slip_inner += wheels[0].slip_y, sum.lat_slip_outer += wheels[1].slip_y;
    for (std::size_t i = 0; i < 4; ++i) sum.load_n[i] += wheels[i].load_n;
    for (std::size_t i = 0; i < 4; ++i) sum.force_y_n[i] += wheels[i].force_y_n;
    for (std::size_t i = 0; i < 4; ++i) sum.steer_rad[i] += wheels[i].steer_angle_rad;
    v_min = std::min(v_min, v), v_max = std::max(v_max, v);
    ++n;
    if (phase + h < step_s) continue;  // the step's last sample: close it
    SteadyPoint p{sum.speed_mps / n,    targets.target_speed_mps(t),  sum.lat_accel_mps2 / n,
                  sum.radius_m / n,     sum.road_wheel_steer_rad / n, sum.steering_wheel_rad / n,
                  sum.rack_force_n / n, sum.lat_slip_inner / n,       sum.lat_slip_outer / n};
    for (double& f : sum.load_n) f /= n;
    p.load_n = sum.load_n;
    for (std::size_t i = 0; i < 4; ++i) p.force_y_n[i] = sum.force_y_n[i] / n;
    for (std::size_t i = 0; i < 4; ++i) p.steer_rad[i] = sum.steer_rad[i] / n;
    p.steady = std::abs(p.speed_mps - p.target_mps) < 0.25 && v_max - v_min < 0.1 &&
               std::abs(p.radius_m / dp.circle_radius_m - 1) < 0.03;
    points.push_back(p);
    sum = {}, n = 0, v_min = 1e9, v_max = 0;
  }
  return points;
}

/// Least-squares slope of y over x of the steady points with x in [lo, hi].
template <class X, class Y>
double slope(const std::vector<SteadyPoint>& pts, double lo, double hi, X x, Y y, int* count) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (const auto& p : pts) {
    const double a = x(p);
    if (!p.steady || a < lo || a > hi) continue;
    const double b = y(p);
    sx += a, sy += b, sxx += a * a, sxy += a * b, n += 1;
  }
  *count = static_cast<int>(n);
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// TMeasy's lateral force below its peak (Rill 2011, sec. 3.4: F = dF0 s / (1 + sigma (sigma +
/// dF0 s_M / F_M - 2)), sigma = s / s_M; `linear`: dF0 s) at a wheel load, the curve's
/// parameters interpolated between F_zN and 2 F_zN as model/tire does.
double lateral_force_n(const model::tire::TmeasyParams& t, double load_n, double slip,
                       bool linear) {
  const auto c = model::tire::characteristic_at(t, load_n, 1.0).y;
  const double sigma = linear ? 0.0 : slip / c.max_slip;
  return c.initial_slope_n * slip /
         (1 + sigma * (sigma + c.initial_slope_n * c.max_slip / c.max_force_n - 2));
}

/// The nonlinear single-track reference (a textbook steady state, not the model): both tires of
/// an axle at one slip carry the axle's lateral force on the TMeasy curve at their loads
/// (bisection), and delta - l/R = atan(s_f) - atan(s_r).
struct AxleLoads {
  std::array<double, 4> load_n{};  ///< FL, FR, RL, RR
  double front_force_n = 0, rear_force_n = 0;
  bool linear = false;
};

/// The x in [lo, hi] where the rising function f(x) reaches `target` (bisection).
template <class F>
double bisect(F f, double lo, double hi, double target) {
  for (int k = 0; k < 60; ++k) {
    const double x = 0.5 * (lo + hi);
    (f(x) < target ? lo : hi) = x;
  }
  return 0.5 * (lo + hi);
}

double axle_slip(const model::tire::TmeasyParams& t, double load_a_n, double load_b_n,
                 double force_n, bool linear) {
  const double hi =
      0.5 * model::tire::characteristic_at(t, std::min(load_a_n, load_b_n), 1.0).y.max_slip;
  return bisect(
      [&](double s) {
        return lateral_force_n(t, load_a_n, s, linear) + lateral_force_n(t, load_b_n, s, linear);
      },
      0.0, hi, force_n);
}

double reference_steer_rad(const model::vehicle::VehicleParams& vp, const AxleLoads& a) {
  const auto& fz = a.load_n;
  return std::atan(axle_slip(vp.axles[0].tire.tmeasy, fz[0], fz[1], a.front_force_n, a.linear)) -
         std::atan(axle_slip(vp.axles[1].tire.tmeasy, fz[2], fz[3], a.rear_force_n, a.linear));
}

/// The lateral slip of a free-rolling wheel at (x, y) from the CG, steered by gamma, on a steady
/// circle: its contact point moves with the body, (v - r y, v_y + r x); in the wheel's frame
/// s_y = -v_lat / |v_long| (TMeasy's lateral slip, eq. 15 before normalizing).
double wheel_lateral_slip(double v, double v_y, double r, double x, double y, double gamma) {
  const double ux = v - r * y, uy = v_y + r * x;
  const double v_long = std::cos(gamma) * ux + std::sin(gamma) * uy;
  const double v_lat = -std::sin(gamma) * ux + std::cos(gamma) * uy;
  return -v_lat / std::abs(v_long);
}

/// The sum of an axle's two lateral tire forces (left, right: wheels 2j, 2j + 1) on the tire
/// curve, each wheel at its own place and steer.
double axle_force_n(const model::vehicle::AxleParams& axle, const std::array<double, 4>& load_n,
                    std::size_t j, double v, double v_y, double r,
                    const std::array<double, 2>& steer_rad) {
  double f = 0;
  for (std::size_t side = 0; side < 2; ++side) {
    const double y = (side == 0 ? 0.5 : -0.5) * axle.track_m;
    const double s = wheel_lateral_slip(v, v_y, r, axle.position_x_m, y, steer_rad[side]);
    f += lateral_force_n(axle.tire.tmeasy, load_n[2 * j + side], s, false);
  }
  return f;
}

/// The two-track steady state (a textbook two-track model at the logged loads and axle forces,
/// not the model): the rear tires, each at its own slip from the body's lateral speed v_y and
/// its place on the circle, carry the rear axle's force (v_y by bisection); the front tires,
/// steered gamma +- toe/2 with the logged toe split, carry the front's (gamma by bisection).
double two_track_steer_rad(const model::vehicle::VehicleParams& vp, const SteadyPoint& p) {
  const double v = p.speed_mps, r = v / p.radius_m;
  const auto& w = p.steer_rad;
  const double v_y = -bisect(  // the rear force grows as the rear slides outwards (-v_y)
      [&](double u) {
        return axle_force_n(vp.axles[1], p.load_n, 1, v, -u, r, {w[2], w[3]});
      },
      -0.2 * v, 0.2 * v, p.force_y_n[2] + p.force_y_n[3]);
  const double toe_rad = w[0] - w[1];
  return bisect(
      [&](double g) {
        return axle_force_n(vp.axles[0], p.load_n, 0, v, v_y, r,
                            {g + 0.5 * toe_rad, g - 0.5 * toe_rad});
      },
      -0.3, 0.3, p.force_y_n[0] + p.force_y_n[1]);
}

/// The references' inputs at a steady point, each adding one effect: the static loads and the
/// axle shares m_i a_y of the lateral force (m_i = axle load / g; linear or on the tire curve),
/// the logged wheel loads (lateral load transfer), the logged axle forces (the split the yaw
/// balance gives with the aligning torques of the pneumatic and caster trails), and last the
/// two tracks: each wheel at its own slip (two_track_steer_rad).
enum class Effects { kLinear, kTireCurve, kLoadTransfer, kForceSplit, kTwoTrack };

AxleLoads reference_inputs(const SteadyPoint& p, const std::array<double, 4>& static_load_n,
                           Effects e) {
  AxleLoads a;
  a.linear = e == Effects::kLinear;
  a.load_n = e <= Effects::kTireCurve ? static_load_n : p.load_n;
  const double g = 9.81, ay = p.lat_accel_mps2;
  a.front_force_n = (a.load_n[0] + a.load_n[1]) / g * ay;
  a.rear_force_n = (a.load_n[2] + a.load_n[3]) / g * ay;
  if (e == Effects::kForceSplit) {
    a.front_force_n = p.force_y_n[0] + p.force_y_n[1];
    a.rear_force_n = p.force_y_n[2] + p.force_y_n[3];
  }
  return a;
}

TEST(Vehicle, SteadyCircleIso4138ConstantRadius) {
  const RigConfig c = load_config(RIG_SOURCE_DIR "/config/maneuvers/circle-iso4138.toml");
  ASSERT_TRUE(c.path_driver && c.model.vehicle);
  const model::vehicle::VehicleParams& vp = c.model.vehicle->params;
  const double l = vp.axles[0].position_x_m - vp.axles[1].position_x_m;
  const double i_s = vp.steering.steering_arm_m / vp.steering.rack_per_pinion_m_per_rad;
  const std::vector<SteadyPoint> pts = run_circle(c);
  double ay_max = 0;
  for (const auto& p : pts) {
    std::printf(
        "circle R %.2f m, v %.2f m/s (target %.1f)%s: a_y %.3f m/s^2, road wheels %.6f rad, "
        "steering wheel %.4f rad, rack force %.0f N, front slips %.3f %.3f\n",
        p.radius_m, p.speed_mps, p.target_mps, p.steady ? "" : " NOT STEADY", p.lat_accel_mps2,
        p.road_wheel_steer_rad, p.steering_wheel_rad, p.rack_force_n, p.lat_slip_inner,
        p.lat_slip_outer);
    if (p.steady) ay_max = std::max(ay_max, p.lat_accel_mps2);
  }
  // Understeer gradient (ISO 4138, at the road wheels): K = d(delta - l/R)/d(a_y), delta the mean
  // steer angle of the front wheels (after the tie-rod compliance) and R the radius driven
  // (v / r, held within 2 % of 40 m: l/R is nearly constant, its slope is taken out).
  const auto ay = [](const SteadyPoint& p) { return p.lat_accel_mps2; };
  int n_k = 0, n_sw = 0, n_low = 0, n_high = 0;
  const double k = slope(
      pts, 0.0, 4.0, ay,
      [&](const SteadyPoint& p) { return p.road_wheel_steer_rad - l / p.radius_m; }, &n_k);
  // the same from the steering-wheel angle over the overall ratio: adds the compliance steer of
  // the tie rods and torsion bar under the aligning torque
  const double k_sw = slope(
      pts, 0.0, 4.0, ay,
      [&](const SteadyPoint& p) { return p.steering_wheel_rad / i_s - l / p.radius_m; }, &n_sw);
  // the single-track references over the same points, one effect added at a time
  std::array<double, 4> static_load_n{};  // the slowest point's loads, left and right averaged
  for (std::size_t i = 0; i < 4; ++i)
    static_load_n[i] = 0.5 * (pts.front().load_n[i] + pts.front().load_n[i ^ 1U]);
  std::array<double, 5> k_ref{};
  for (Effects e : {Effects::kLinear, Effects::kTireCurve, Effects::kLoadTransfer,
                    Effects::kForceSplit, Effects::kTwoTrack}) {
    int n_ref = 0;
    k_ref[static_cast<std::size_t>(e)] = slope(
        pts, 0.0, 4.0, ay,
        [&](const SteadyPoint& p) {
          if (e == Effects::kTwoTrack) return two_track_steer_rad(vp, p) - l / p.radius_m;
          return reference_steer_rad(vp, reference_inputs(p, static_load_n, e));
        },
        &n_ref);
  }
  std::printf(
      "single-track references, a_y <= 4: linear %.6f rad/(m/s^2), + the tire curve's bend "
      "%.6f, + lateral load transfer %.6f, + the axle force split of the logged forces %.6f "
      "(model %+.1f %%); two-track, each wheel its own slip (its place, the logged toe split "
      "%.2f mrad at the slowest point) %.6f; model %.6f (%+.1f %%)\n",
      k_ref[0], k_ref[1], k_ref[2], k_ref[3], 100 * (k / k_ref[3] - 1),
      1e3 * (pts.front().steer_rad[0] - pts.front().steer_rad[1]), k_ref[4], k,
      100 * (k / k_ref[4] - 1));
  const auto rack = [](const SteadyPoint& p) { return p.rack_force_n; };
  const double rack_low = slope(pts, 1.0, 3.0, ay, rack, &n_low);
  const double rack_high = slope(pts, 8.0, 9.2, ay, rack, &n_high);
  std::printf(
      "ISO 4138 R = 40 m: understeer gradient %.6f rad/(m/s^2) at the road wheels (%d points, "
      "a_y <= 4), %.6f from the steering wheel / %.1f; steady maximum a_y %.2f m/s^2; "
      "d(rack force)/d(a_y) %.1f N/(m/s^2) over 1-3 m/s^2 (%d points), %.1f over 8-9 (%d "
      "points): ratio %.3f\n",
      k, n_k, k_sw, i_s, ay_max, rack_low, n_low, rack_high, n_high, rack_high / rack_low);
  // The linear single-track value m_f/C_f - m_r/C_r of tests/model/vehicle is 0.00049 (the
  // linear reference here reproduces it). Up to 4 m/s^2 the model's understeer is not linear:
  // the tire curve bends early (Rill's passenger-car data), the front-heavy roll stiffness
  // shifts load on TMeasy's degressive load law, and the aligning torques shift lateral force to
  // the front axle (K is a small difference of two slips: 0.4 % of the force moved to the front
  // is +20 % of K). And a single track has one slip per axle, the model's two wheels do not:
  // the inner wheel's path is tighter (in front l t / R^2 = 2.7 mrad more steer than the outer,
  // no Ackermann), and the steered wheels are not parallel: the tie rods' compliance under each
  // wheel's moment about its steering axis splits their toe. With the sedan's caster, kingpin
  // inclination and scrub the straight-ahead jacking torques F_z (r_s sin sigma + n_c sin delta)
  // = 21 N m per wheel, equal and opposite, stretch one tie rod and compress the other: by hand
  // 21 / (arm^2 c) = 0.8 mrad per wheel; the split moves from +0.3 to -1.1 mrad. As the load
  // shifts outwards, the outer tire's cornering stiffness grows against the inner's, so a slip
  // split between them gives more axle force with a_y: K falls. Measured: the single-track
  // force-split reference is 8.5 % above the model with the geometry (2.2 % without); the
  // two-track one, which holds all four effects, 2.1 % (1.5 %). What remains is of the order
  // of the longitudinal slips, which the pure lateral curve here leaves out: with the logged
  // ones in model/tire's combined law (eq. 16) the two-track reference lies 1.7 % below the
  // model instead of 2.1 % above (measured once; not kept: that is the model's own tire law).
  EXPECT_GE(n_k, 6);
  EXPECT_NEAR(k_ref[0], 0.00049, 0.03 * 0.00049);
  EXPECT_GT(k_ref[1], k_ref[0]);
  EXPECT_GT(k_ref[2], k_ref[1]);
  EXPECT_GT(k_ref[3], k_ref[2]);
  EXPECT_NEAR(k, k_ref[4], 0.05 * k_ref[4]);
  EXPECT_GT(ay_max, 8.5);  // the steady states reach far beyond the front axle's old 7.99
  EXPECT_LT(ay_max, 9.81);
  ASSERT_GE(n_low, 3);
  ASSERT_GE(n_high, 2);
  EXPECT_LE(rack_high, 0.30 * rack_low);
}

}  // namespace
}  // namespace rig
