// The maneuvers' KPIs (rig/kpi) against closed-form answers: ISO 7401 step response of a
// second-order system, ISO 4138 understeer gradient of synthetic steady states, braking
// distance and UN ECE R13-H mean fully developed deceleration of a known deceleration, ISO
// 3888-1 lanes kept and cones hit of hand-placed poses; and their [[kpi]] keys.

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/config_error.h"
#include "rig/kpi/braking_kpis.h"
#include "rig/kpi/circle_kpis.h"
#include "rig/kpi/iso3888_kpis.h"
#include "rig/kpi/kpi_recorder.h"
#include "rig/kpi/kpi_spec.h"
#include "rig/kpi/step_response_kpis.h"
#include "tests/support/config_error_of.h"

namespace rig::kpi {
namespace {

constexpr double kPi = std::numbers::pi;

/// The root of f in [a, b] (f(a), f(b) of opposite signs) by bisection: the test's own solver.
double bisect(const std::function<double(double)>& f, double a, double b) {
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    ((f(a) < 0) == (f(m) < 0) ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// ---- ISO 7401: a step of the input at t = 1 s into y = G d (1 - e^(-z w tau) (cos wd tau +
// z / sqrt(1 - z^2) sin wd tau)), tau = t - 1 s: peak at tau = pi / wd, overshoot
// exp(-z pi / sqrt(1 - z^2)), 90 % of the change where the bracket is 0.9 (found by bisection).
struct SecondOrder {
  double gain = 0.3, zeta = 0.5, omega = 2 * kPi * 1.2, step = 0.5;
  [[nodiscard]] double wd() const { return omega * std::sqrt(1 - zeta * zeta); }
  [[nodiscard]] double unit(double tau) const {
    if (tau < 0) return 0.0;
    return 1 -
           std::exp(-zeta * omega * tau) *
               (std::cos(wd() * tau) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd() * tau));
  }
};

TEST(StepResponseKpis, SecondOrderStepHasItsClosedFormMeasures) {
  const SecondOrder s;
  const double h = 1e-4;
  std::vector<double> t, x, y;
  for (int i = 0; i <= 80000; ++i) {  // 0 .. 8 s
    t.push_back(i * h);
    const bool on = i >= 10000;  // the input's step: 0 at 0.9999 s, d at 1.0 s
    x.push_back(on ? s.step : 0.0);
    y.push_back(s.gain * s.step * s.unit(t.back() - 1.0));
  }
  const StepResponse r = step_response(t, y, x, 1.0, 0.9);
  const double t_ref = 1.0 - 0.5 * h;  // the 50 % crossing between the two samples
  const double tau90 = bisect([&](double tau) { return s.unit(tau) - 0.9; }, 0.0, kPi / s.wd());
  EXPECT_NEAR(r.response_time_s, 1.0 + tau90 - t_ref, 1e-6);  // linear between samples: O(h^2)
  EXPECT_NEAR(r.peak_response_time_s, 1.0 + kPi / s.wd() - t_ref, h);  // the peak's sample
  EXPECT_NEAR(r.overshoot, std::exp(-s.zeta * kPi / std::sqrt(1 - s.zeta * s.zeta)), 1e-6);
  EXPECT_NEAR(r.steady_gain, s.gain, 1e-9);
  // a step to the right: the same measures, the gain's sign kept
  for (auto& v : x) v = -v;
  for (auto& v : y) v = -v;
  const StepResponse l = step_response(t, y, x, 1.0, 0.9);
  EXPECT_NEAR(l.response_time_s, r.response_time_s, 1e-12);
  EXPECT_NEAR(l.overshoot, r.overshoot, 1e-12);
  EXPECT_NEAR(l.steady_gain, s.gain, 1e-9);
  // no step: no answer
  const std::vector<double> flat(t.size(), 0.2);
  EXPECT_TRUE(std::isnan(step_response(t, y, flat, 1.0, 0.9).response_time_s));
}

// ---- ISO 4138: steady states on R = 40 m at 3..19 m/s (8 s each, the last 3 s averaged) whose
// steering-wheel angle is i_s (l / R + K a_y) up to a_y = 4 m/s^2 (plus a bend above it, and
// transients in the first 5 s of each plateau): the slope over a_y <= 4 is K.
TEST(CircleKpis, UndersteerGradientOfSyntheticSteadyStates) {
  CircleParams p;
  p.plateau_s = 8.0;
  p.steering_ratio = 15.7;
  p.wheelbase_m = 2.8;
  const double radius = 40.0, k = 0.0007, h = 1e-3;
  std::vector<double> t, angle, v, r;
  for (int j = 0; j < 17; ++j) {
    const double speed = 3.0 + j;
    const double ay = speed * speed / radius;
    const double bend = ay > 4.0 ? 0.01 * (ay - 4.0) * (ay - 4.0) : 0.0;
    const double steady = p.steering_ratio * (p.wheelbase_m / radius + k * ay + bend);
    for (int i = 1; i <= 8000; ++i) {
      const double ts = j * 8.0 + i * h;
      const bool transient = i * h < 5.0;
      // plateau 2 wanders by 0.3 m/s in its steady part: not steady, its angle must not count
      const double wobble = j == 2 && !transient ? 0.3 * std::sin(i * h) : 0.0;
      t.push_back(ts);
      v.push_back(speed + (transient ? 0.5 : wobble));
      r.push_back(speed / radius);
      angle.push_back(transient ? 1.0 : (j == 2 ? 0.5 : steady));
    }
  }
  EXPECT_NEAR(understeer_gradient(t, angle, v, r, p), k, 1e-9);
  // right turns (r, the angle and so a_y negative): the same K
  for (auto& x : r) x = -x;
  for (auto& x : angle) x = -x;
  EXPECT_NEAR(understeer_gradient(t, angle, v, r, p), k, 1e-9);
  p.ay_max_mps2 = 0.2;  // a range with one steady state (3 m/s: 0.225 is out, none in)
  EXPECT_TRUE(std::isnan(understeer_gradient(t, angle, v, r, p)));
}

// ---- Braking: 27.78 m/s held to the brake point (the pressure crosses 1 bar at t = 2 s), the
// deceleration building up linearly to a = 8 m/s^2 over T = 0.3 s, then constant: v = v0 -
// a t^2 / (2 T), s = v0 t - a t^3 / (6 T) during the build-up; then s1 + (v1^2 - v^2) / (2 a).
// The build-up ends at 26.58 m/s, above 0.8 v0, so the MFDD is a exactly.
TEST(BrakingKpis, DistanceAndMeanDecelerationOfAKnownDeceleration) {
  const double v0 = 27.78, a = 8.0, build = 0.3, h = 1e-3, stop = 0.01;
  std::vector<double> t, v, p;
  for (int i = 0; i <= 8000; ++i) {
    const double ts = i * h, tb = ts - 2.0;
    double speed = v0;
    if (tb > 0)
      speed = tb < build ? v0 - a * tb * tb / (2 * build) : v0 - a * build / 2 - a * (tb - build);
    t.push_back(ts);
    v.push_back(std::max(0.0, speed));
    p.push_back(tb >= 0 ? 1e5 + 1e7 * tb : 0.0);
  }
  const auto from = brake_point(p, 1e5, v.size());
  ASSERT_TRUE(from);
  EXPECT_EQ(*from, 2000u);
  const double v1 = v0 - a * build / 2, s1 = v0 * build - a * build * build / 6;
  EXPECT_NEAR(braking_distance(t, v, *from, stop), s1 + (v1 * v1 - stop * stop) / (2 * a), 1e-5);
  EXPECT_NEAR(mean_deceleration(t, v, *from), a, 1e-9);
  // without a trigger the window's start is the brake point: 2 s at v0 more
  EXPECT_NEAR(braking_distance(t, v, 0, stop), 2 * v0 + s1 + (v1 * v1 - stop * stop) / (2 * a),
              1e-5);
  EXPECT_FALSE(brake_point(p, 1e9, v.size()));  // never braked
  std::vector<double> cruising(v.size(), v0);
  EXPECT_TRUE(std::isnan(braking_distance(t, cruising, 0, stop)));  // never stopped
}

// ---- ISO 3888-1: the sedan's outline (1.80 m x 4.70 m, front 2.10 m ahead of the CG); lane 1
// half-width (1.1 b + 0.25) / 2 = 1.115 m, lane 3 (1.2 b + 0.25) / 2 = 1.205 m around y = 3.5,
// lane 5 (1.3 b + 0.25) / 2 = 1.295 m.
Iso3888Params sedan_track() {
  Iso3888Params p;
  p.start_x_m = 0.0;
  p.vehicle_width_m = 1.8;
  p.vehicle_length_m = 4.7;
  p.cg_to_front_m = 2.1;
  return p;
}

struct Poses {
  std::vector<double> x, y, yaw;
  void add(double px, double py, double pyaw = 0.0) {
    x.push_back(px), y.push_back(py), yaw.push_back(pyaw);
  }
  /// Along y from x0 to x1 in 0.1 m steps.
  void straight(double x0, double x1, double py) {
    for (double px = x0; px <= x1 + 1e-9; px += 0.1) add(px, py);
  }
};

TEST(Iso3888Kpis, LanesKeptByTheOutline) {
  const Iso3888Params p = sedan_track();
  const auto lanes = iso3888_lanes(p);
  ASSERT_EQ(lanes.size(), 3u);
  EXPECT_NEAR(lanes[0].width_m, 2.23, 1e-12);
  EXPECT_NEAR(lanes[1].width_m, 2.41, 1e-12);
  EXPECT_NEAR(lanes[2].width_m, 2.59, 1e-12);
  // straight along y: lanes 1 and 5 kept at y = 0.2 (edge 1.10 < 1.115), lane 1 lost at 0.25
  Poses a;
  a.straight(-10, 130, 0.2);
  EXPECT_DOUBLE_EQ(lanes_kept(p, a.x, a.y, a.yaw), 2.0);  // lane 3 is 3.5 m to the left
  Poses b;
  b.straight(-10, 130, 0.25);
  EXPECT_DOUBLE_EQ(lanes_kept(p, b.x, b.y, b.yaw), 1.0);
  // on each lane's centre: all three; not through to the end: none
  Poses c;
  c.straight(-10, 40, 0.0), c.straight(45, 70, 3.5), c.straight(95, 130, 0.0);
  EXPECT_DOUBLE_EQ(lanes_kept(p, c.x, c.y, c.yaw), 3.0);
  Poses d;
  d.straight(-10, 40, 0.0), d.straight(45, 70, 3.5), d.straight(95, 110, 0.0);
  EXPECT_DOUBLE_EQ(lanes_kept(p, d.x, d.y, d.yaw), 0.0);
  // yawed in lane 1 at y = 0: the rear corner swings out to 2.6 sin(psi) + 0.9 cos(psi), the
  // limit is 1.115 m: lane 1 is kept just below that yaw, lost just above it
  const double psi =
      bisect([](double s) { return 2.6 * std::sin(s) + 0.9 * std::cos(s) - 1.115; }, 0.0, 0.5);
  for (const double yaw : {psi - 1e-6, psi + 1e-6}) {
    Poses e = c;
    e.add(7.5, 0.0, yaw);
    EXPECT_DOUBLE_EQ(lanes_kept(p, e.x, e.y, e.yaw), yaw < psi ? 3.0 : 2.0) << yaw;
  }
}

TEST(Iso3888Kpis, ConesHitWithinTheirBaseRadius) {
  const Iso3888Params p = sedan_track();  // cones every 5 m, base radius 0.15 m
  // y = 0.25: the left edge at 1.15 m, lane 1's left cones at 1.115 + 0.15 = 1.265 m (0.115 m
  // away: hit, x = 0, 5, 10, 15); lane 5's at 1.445 m (0.295 m: missed), lane 3's right ones at
  // 3.5 - 1.205 - 0.15 = 2.145 m (missed)
  Poses a;
  a.straight(-10, 130, 0.25);
  EXPECT_DOUBLE_EQ(cones_hit(p, a.x, a.y, a.yaw), 4.0);
  Poses c;
  c.straight(-10, 40, 0.0), c.straight(45, 70, 3.5), c.straight(95, 130, 0.0);
  EXPECT_DOUBLE_EQ(cones_hit(p, c.x, c.y, c.yaw), 0.0);
  // one pose with the front left corner (x + 2.1, y + 0.9) 1 mm within 0.15 m of the cone at
  // (5, 1.265), diagonally (the rear left corner is then 0.22 m from the cone at x = 0): hit;
  // 1 mm beyond: missed
  for (const double gap : {0.149, 0.151}) {
    Poses e = c;
    const double d = gap / std::sqrt(2.0);
    e.add(5.0 - 2.1 - d, 1.265 - 0.9 - d);
    EXPECT_DOUBLE_EQ(cones_hit(p, e.x, e.y, e.yaw), gap < 0.15 ? 1.0 : 0.0) << gap;
  }
}

// ---- [[kpi]] keys of the maneuver kinds and what they record
std::vector<KpiSpec> parse(const std::string& text) {
  const toml::table doc = toml::parse(std::string_view(text), std::string("kpis.toml"));
  io::config::StrictTable top(doc, "kpis.toml", "top level");
  return read_kpis(top, io::signals::Catalogue::two_axle_vehicle(), {2.8, 15.7});
}

std::string message_of(const std::string& text) {
  return test::config_error_of([&] { parse(text); });
}

TEST(ManeuverKpiSpec, ReadsTheKindsKeysAndUnits) {
  const auto k = parse(R"(
[[kpi]]
name = "t90"
kind = "response_time"
signal = "yaw_rate_radps"
versus = "steering_wheel_angle_rad"
from_s = 0.5
steady_s = 1.5
fraction = 0.8
max = 0.3
[[kpi]]
name = "gain"
kind = "steady_gain"
signal = "yaw_rate_radps"
versus = "steering_wheel_angle_rad"
[[kpi]]
name = "K"
kind = "understeer_gradient"
plateau_s = 8
[[kpi]]
name = "s"
kind = "braking_distance"
trigger = "brake_pressure_front_pa"
threshold = 1e5
[[kpi]]
name = "cones"
kind = "iso3888_cones_hit"
start_x_m = 30
vehicle_width_m = 1.8
vehicle_length_m = 4.7
cg_to_front_m = 2.1
max = 0
)");
  ASSERT_EQ(k.size(), 5u);
  EXPECT_EQ(k[0].kind, KpiKind::kResponseTime);
  EXPECT_EQ(k[0].unit, "s");
  EXPECT_DOUBLE_EQ(k[0].steady_s, 1.5);
  EXPECT_DOUBLE_EQ(k[0].fraction, 0.8);
  EXPECT_TRUE(k[0].records_versus);
  EXPECT_EQ(k[1].unit, "rad/s/(rad)");
  EXPECT_EQ(k[2].unit, "rad/(m/s^2)");
  EXPECT_EQ(k[2].signal_name, "unit1.steering.wheel_angle_rad");
  EXPECT_DOUBLE_EQ(k[2].circle.steering_ratio, 15.7);  // the vehicle's, by default
  EXPECT_DOUBLE_EQ(k[2].circle.steady_s, 3.0);
  EXPECT_TRUE(k[2].records_aux);
  EXPECT_EQ(k[3].unit, "m");
  EXPECT_EQ(k[3].signal_name, "unit1.speed_x_mps");
  EXPECT_DOUBLE_EQ(k[3].threshold, 1e5);
  EXPECT_EQ(k[4].unit, "1");
  EXPECT_DOUBLE_EQ(k[4].track.start_x_m, 30.0);
  EXPECT_DOUBLE_EQ(k[4].track.cone_radius_m, 0.15);
  EXPECT_EQ(k[4].aux_name, "unit1.yaw_rad");
}

TEST(ManeuverKpiSpec, BadKeysAreNamed) {
  const std::string head = "[[kpi]]\nname = \"k\"\n";
  EXPECT_NE(message_of(head + "kind = \"overshoot\"\nsignal = \"yaw_rate_radps\"\n")
                .find("needs 'versus'"),
            std::string::npos);
  EXPECT_NE(message_of(head + "kind = \"understeer_gradient\"\n").find("needs 'plateau_s'"),
            std::string::npos);
  EXPECT_NE(message_of(head + "kind = \"understeer_gradient\"\nplateau_s = 8\nsteady_s = 9\n")
                .find("steady_s: value 9 out of range [0.001, 8]"),
            std::string::npos);
  EXPECT_NE(
      message_of(head + "kind = \"braking_distance\"\ntrigger = \"brake_pressure_front_pa\"\n")
          .find("needs 'threshold'"),
      std::string::npos);
  EXPECT_NE(
      message_of(head + "kind = \"iso3888_lanes_kept\"\nstart_x_m = 30\n").find("vehicle_width_m"),
      std::string::npos);
  // a key of another kind is unknown here
  EXPECT_NE(message_of(head + "kind = \"mean_deceleration\"\nstop_mps = 0.1\n")
                .find("unknown key 'stop_mps'"),
            std::string::npos);
  EXPECT_NE(
      message_of(head + "kind = \"iso3888_lanes_kept\"\nstart_x_m = 0\nvehicle_width_m = 1.8\n"
                        "vehicle_length_m = 4.7\ncg_to_front_m = 2.1\ncone_radius_m = 0.1\n")
          .find("unknown key 'cone_radius_m'"),
      std::string::npos);
}

// The recorder records what each kind needs and evaluates it: a braking run's series.
TEST(ManeuverKpiSpec, EvaluateRoutesTheSeries) {
  auto k = parse("[[kpi]]\nname = \"d\"\nkind = \"mean_deceleration\"\nmin = 5\n");
  Series s;
  for (int i = 0; i <= 400; ++i) {
    s.time_s.push_back(i * 0.01);
    s.y.push_back(std::max(0.0, 20.0 - 6.0 * i * 0.01));
  }
  const KpiResult r = evaluate(k[0], s);
  EXPECT_NEAR(r.value, 6.0, 1e-9);
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.unit, "m/s^2");
}

}  // namespace
}  // namespace rig::kpi
