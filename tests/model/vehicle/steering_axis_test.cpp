// The steering-axis geometry (issue 15, item 2; model/vehicle/steering/steering_axis.h): the
// jacking torque against a brute-force rigid disc turned about the inclined axis (an independent
// construction with Eigen's AngleAxis, the lowest rim point by sampling, the moment as -dV/dpsi
// by central differences), restoring on both wheels, and the moments of F_x: braking on the
// scrub radius, driving on the spindle offset.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "io/config/vehicle_file.h"
#include "model/report.h"
#include "model/tire/tmeasy_bore.h"
#include "model/vehicle/steering/steering_axis.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::vehicle {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kLoadN = 4000, kRadiusM = 0.31;

AxleParams sedan_axis() {
  AxleParams a;
  a.steered = true;
  a.caster_angle_rad = 6 * kDeg;
  a.caster_trail_m = 0.020;
  a.kingpin_inclination_rad = 12 * kDeg;
  a.scrub_radius_m = 0.010;
  return a;
}

/// The height of a rigid disc's lowest point after turning it by psi about the steering axis,
/// built directly for either wheel (side +1 left, -1 right: the axis' ground point inboard by
/// r_s, its top inwards and rearwards), contact centre at the origin, wheel centre at (0, 0, R).
double lowest_point_m(const AxleParams& a, int side, double psi, double radius_m = kRadiusM) {
  const double sd = side;
  const Eigen::Vector3d ground(a.caster_trail_m, -sd * a.scrub_radius_m, 0);
  const Eigen::Vector3d axis =
      Eigen::Vector3d(-std::tan(a.caster_angle_rad), -sd * std::tan(a.kingpin_inclination_rad), 1)
          .normalized();
  const Eigen::AngleAxisd turn(psi, axis);
  const Eigen::Vector3d centre = ground + turn * (Eigen::Vector3d(0, 0, radius_m) - ground);
  const Eigen::Vector3d u = turn * Eigen::Vector3d::UnitX(), v = turn * Eigen::Vector3d::UnitZ();
  double lowest = 1e9;
  constexpr int kSamples = 200000;
  for (int i = 0; i < kSamples; ++i) {  // the rim, around its bottom
    const double t = std::numbers::pi * (0.25 + 0.5 * i / kSamples);
    lowest = std::min(lowest, (centre + radius_m * (std::cos(t) * u - std::sin(t) * v)).z());
  }
  return lowest;
}

/// -dV/dpsi, V = F_z * lift = -F_z h_lowest (psi the wheel's steer, + left, both wheels in the
/// same frame: the right wheel's construction above is its own, not a mirrored left one).
double brute_jacking_nm(const AxleParams& a, int side, double steer_rad, double load_n = kLoadN,
                        double radius_m = kRadiusM) {
  const double d = 1e-4;
  return load_n *
         (lowest_point_m(a, side, steer_rad + d, radius_m) -
          lowest_point_m(a, side, steer_rad - d, radius_m)) /
         (2 * d);
}

double jacking_nm(const AxleParams& a, int side, double steer_rad) {
  SteeringAxisLoads loads;
  loads.load_n = kLoadN;
  loads.wheel_radius_m = kRadiusM;
  return steering_axis_moment_nm(a, loads, steer_rad, side);
}

TEST(SteeringAxis, JackingTorqueAgainstTheTurnedDisc) {
  const AxleParams a = sedan_axis();
  for (const double steer : {-0.5, -0.2, 0.05, 0.2, 0.5}) {
    for (const int side : {1, -1}) {
      const double model = jacking_nm(a, side, steer);
      const double brute = brute_jacking_nm(a, side, steer);
      std::printf("steer %+.2f side %+d: jacking %8.3f N m, turned disc %8.3f\n", steer, side,
                  model, brute);
      EXPECT_NEAR(model, brute, 0.02 * std::abs(brute) + 0.01);
    }
  }
}

// Restoring on both wheels: steered left, each wheel's moment falls below its value straight
// ahead (the straight-ahead moments of caster and scrub are equal and opposite left/right and
// cancel on the rack); the pair's restoring slope is about the kingpin inclination's
// -2 F_z (r_s + R tan delta) sin delta (the spindle offset's lift), less the caster's lowering
// of the cambering disc.
TEST(SteeringAxis, JackingRestoresOnBothWheels) {
  const AxleParams a = sedan_axis();
  const double psi = 0.2;
  for (const int side : {1, -1}) {
    EXPECT_LT(jacking_nm(a, side, psi) - jacking_nm(a, side, 0), 0) << side;
    EXPECT_GT(jacking_nm(a, side, -psi) - jacking_nm(a, side, 0), 0) << side;
  }
  EXPECT_NEAR(jacking_nm(a, 1, 0) + jacking_nm(a, -1, 0), 0, 1e-9);
  // the slope at psi -> 0, the model's against the turned disc's
  const double slope = (jacking_nm(a, 1, 1e-3) + jacking_nm(a, -1, 1e-3)) / 1e-3;
  const double brute = (brute_jacking_nm(a, 1, 1e-2) + brute_jacking_nm(a, -1, 1e-2)) / 1e-2;
  const double kpi_only =
      -2 * kLoadN * (a.scrub_radius_m + kRadiusM * std::tan(12 * kDeg)) * std::sin(12 * kDeg);
  std::printf("restoring slope of the pair: %.1f N m/rad (turned disc %.1f; KPI term alone %.1f)\n",
              slope, brute, kpi_only);
  EXPECT_NEAR(slope, brute, 0.02 * std::abs(brute));
  EXPECT_LT(slope, 0.5 * kpi_only);  // the KPI's lift dominates the caster's lowering
}

// Braking the left wheel alone (F_x < 0 at the contact, outboard of the axis by r_s): the
// moment -r_s F_x e_z steers it left (toe-out), the right wheel braked steers right; a drive
// torque T_s acts as the drive force T_s / R at the wheel centre, on the spindle offset.
TEST(SteeringAxis, LongitudinalForcesOnScrubAndSpindleOffset) {
  AxleParams a;
  a.steered = true;
  a.scrub_radius_m = 0.01;
  SteeringAxisLoads brake;
  brake.long_force_n = -3000;
  EXPECT_NEAR(steering_axis_moment_nm(a, brake, 0, 1), 30.0, 1e-12);    // = -r_s F_x
  EXPECT_NEAR(steering_axis_moment_nm(a, brake, 0, -1), -30.0, 1e-12);  // mirrored
  const AxleParams s = sedan_axis();
  const double ez =
      1 / std::sqrt(1 + std::pow(std::tan(6 * kDeg), 2) + std::pow(std::tan(12 * kDeg), 2));
  EXPECT_NEAR(steering_axis_moment_nm(s, brake, 0, 1), -0.01 * -3000 * ez, 1e-9);
  SteeringAxisLoads drive;  // steady drive: F_x = T_s / R
  drive.shaft_torque_nm = 600;
  drive.long_force_n = 600 / kRadiusM;
  drive.wheel_radius_m = kRadiusM;
  const double hand = -(0.01 + kRadiusM * std::tan(12 * kDeg)) * drive.long_force_n * ez;
  std::printf("braking 3 kN: %.2f N m; driving 1.94 kN: %.2f N m (hand %.2f)\n",
              steering_axis_moment_nm(s, brake, 0, 1), steering_axis_moment_nm(s, drive, 0, 1),
              hand);
  EXPECT_NEAR(steering_axis_moment_nm(s, drive, 0, 1), hand, 1e-9);
  EXPECT_NEAR(steering_axis_moment_nm(s, drive, 0, -1), -hand, 1e-9);
}

// The defaults: a vertical axis through the contact, only the aligning torque and the caster
// trail's moment of F_y (today's formula, bit for bit).
TEST(SteeringAxis, DefaultsAreTheCasterTrailAlone) {
  AxleParams a;
  a.caster_trail_m = 0.02;
  SteeringAxisLoads l;
  l.lat_force_n = 1234.5;
  l.long_force_n = -2000;
  l.load_n = 4000;
  l.aligning_nm = -33.3;
  l.wheel_radius_m = kRadiusM;
  EXPECT_EQ(steering_axis_moment_nm(a, l, 0.3, 1), -33.3 - 0.02 * 1234.5);
  EXPECT_EQ(steering_axis_moment_nm(a, l, 0.3, -1), -33.3 - 0.02 * 1234.5);
}

// The vehicle file: the keys, the derived spindle offset and the check of a given one.
TEST(SteeringAxis, VehicleFileKeys) {
  const VehicleParams p =
      io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  const AxleParams& f = p.axles[0];
  const double r0 = f.tire.tmeasy.radius_unloaded_m;
  EXPECT_NEAR(f.spindle_offset_m,
              (f.scrub_radius_m + r0 * std::tan(f.kingpin_inclination_rad)) *
                  std::cos(f.kingpin_inclination_rad),
              1e-12);
  std::printf("sedan: caster %.4f rad, trail %.3f m, KPI %.4f rad, scrub %.3f m, spindle %.4f m\n",
              f.caster_angle_rad, f.caster_trail_m, f.kingpin_inclination_rad, f.scrub_radius_m,
              f.spindle_offset_m);
  EXPECT_NEAR(f.spindle_offset_m, 0.0755, 5e-4);
  EXPECT_TRUE(f.tire.tmeasy.bore.enabled);
  // a spindle offset the axis cannot have: the key and the derived value in the message
  std::ifstream in(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  text.replace(text.find("spindle_offset_m = 0.0755"), 25, "spindle_offset_m = 0.0600");
  const auto file = std::filesystem::temp_directory_path() /
                    ("rig_steering_axis_keys_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << text;
  try {
    (void)io::config::load_vehicle_file(file);
    ADD_FAILURE() << "no error";
  } catch (const io::config::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("spindle_offset_m"), std::string::npos) << what;
    EXPECT_NE(what.find("0.07546"), std::string::npos) << what;  // the derived value
  }
  std::filesystem::remove(file);
}

/// The sedan file, optionally with the bore torque switched off.
VehicleParams sedan(bool bore) {
  if (bore) return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  std::ifstream in(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const auto at = text.find("bore_torque = true");
  EXPECT_NE(at, std::string::npos);
  text.replace(at, 18, "bore_torque = false");
  const auto file = std::filesystem::temp_directory_path() /
                    ("rig_steering_axis_test_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << text;
  VehicleParams p = io::config::load_vehicle_file(file);
  std::filesystem::remove(file);
  return p;
}

/// The sedan at rest, the steering robot turning the wheel to `wheel_rad` in 2 s and holding it
/// 1 s (h = 1 ms); returns the last report and the rack force's spread over the last 0.2 s.
struct Held {
  ModelReport report{};
  double rack_force_spread_n = 0;
};
Held turn_and_hold(const VehicleParams& p, double wheel_rad) {
  VehicleModel m(p, 1e-3);
  (void)m.settle(0.0);
  Signals s = test::all_driver_inputs();
  s[Signal::kGearRequest] = 0;
  Held out;
  double lo = 1e9, hi = -1e9;
  for (int k = 1; k <= 3000; ++k) {
    s[Signal::kSteeringWheelAngleCmd] = wheel_rad * std::min(1.0, k / 2000.0);
    EXPECT_EQ(m.step(s), StepStatus::kOk) << k;
    m.fill_report(out.report);
    if (k > 2800) {
      lo = std::min(lo, out.report.steering.rack_force_n);
      hi = std::max(hi, out.report.steering.rack_force_n);
    }
  }
  out.rack_force_spread_n = hi - lo;
  return out;
}

// The static sedan (bore torque off), the rack held at a steer angle: each tie rod carries the
// jacking torque of its wheel through the steering arm, F = -M_jack dgamma/du with
// dgamma/du = 1 / (arm cos gamma) (gamma = asin(u / arm), the generated eq. 29 tables), M_jack
// from the turned disc at the wheel's load and rolling radius: within 2 %, restoring (the rack
// force resists the travel).
TEST(SteeringAxis, StaticSedanTieRodsCarryTheJackingTorque) {
  const VehicleParams p = sedan(false);
  const Held h = turn_and_hold(p, 4.0);
  const UnitReport& u = h.report.units[0];
  const double arm = p.steering.steering_arm_m;
  const double tie[2] = {h.report.steering.tie_rod_force_left_n,
                         h.report.steering.tie_rod_force_right_n};
  for (int side_index = 0; side_index < 2; ++side_index) {
    const WheelReport& w = u.wheels[static_cast<std::size_t>(side_index)];
    const int side = side_index == 0 ? 1 : -1;
    const double hand =
        -brute_jacking_nm(p.axles[0], side, w.steer_angle_rad, w.tire_load_n, w.rolling_radius_m) /
        (arm * std::cos(w.steer_angle_rad));
    std::printf(
        "held rack %.4f m, wheel %d steer %.4f rad, load %.0f N: tie rod %.2f N (hand "
        "%.2f)\n",
        h.report.steering.rack_travel_m, side_index, w.steer_angle_rad, w.tire_load_n,
        tie[side_index], hand);
    EXPECT_NEAR(tie[side_index], hand, 0.02 * std::abs(hand));
  }
  EXPECT_GT(h.report.steering.rack_travel_m, 0.01);
  EXPECT_GT(tie[0] + tie[1], 0);  // restoring: resists the positive travel
}

// With the bore torque (sticking stiffness ~0.7 MN/m per wheel at the rack with d_B / h) the turn
// at stand-still stays stable at h = 1 ms and the held rack force is about the slid bore torques
// plus the jacking through the arms: sum (e_z M_B,max - M_jack) / (arm cos gamma), within 2 %.
TEST(SteeringAxis, StaticSedanWithBoreTorqueHoldsStable) {
  const VehicleParams p = sedan(true);
  const Held h = turn_and_hold(p, 4.0);
  const UnitReport& u = h.report.units[0];
  const double arm = p.steering.steering_arm_m;
  double hand = 0;
  for (int side_index = 0; side_index < 2; ++side_index) {
    const WheelReport& w = u.wheels[static_cast<std::size_t>(side_index)];
    const int side = side_index == 0 ? 1 : -1;
    // about the inclined axis: its component e_z M_B,max
    const double ez = 1 / std::sqrt(1 + std::pow(std::tan(p.axles[0].caster_angle_rad), 2) +
                                    std::pow(std::tan(p.axles[0].kingpin_inclination_rad), 2));
    const double bore = ez * tire::bore_torque_max_nm(p.axles[0].tire.tmeasy, w.tire_load_n, 1.0);
    const double jack =
        brute_jacking_nm(p.axles[0], side, w.steer_angle_rad, w.tire_load_n, w.rolling_radius_m);
    hand += (bore - jack) / (arm * std::cos(w.steer_angle_rad));
    const double tie = side == 1 ? h.report.steering.tie_rod_force_left_n
                                 : h.report.steering.tie_rod_force_right_n;
    std::printf("wheel %d: bore in the tie rod %.2f N m (hand e_z M_B,max %.2f)\n", side_index,
                tie * arm * std::cos(w.steer_angle_rad) + jack, bore);
  }
  std::printf("bore on: held rack force %.1f N (hand %.1f), spread over 0.2 s %.3f N\n",
              h.report.steering.rack_force_n, hand, h.rack_force_spread_n);
  EXPECT_NEAR(h.report.steering.rack_force_n, hand, 0.02 * hand);
  EXPECT_LT(h.rack_force_spread_n, 1.0);
}

}  // namespace
}  // namespace rig::model::vehicle
