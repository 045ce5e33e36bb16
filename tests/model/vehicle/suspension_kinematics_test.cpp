// The kinematic tables of eq. (29) in the vehicle (SuspensionKinematics + VehicleFramework):
// mirroring, given tables, toe and bump steer as physical effects, partial Jacobians vs FD.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/config_error.h"
#include "io/config/vehicle_file.h"
#include "model/solver/finite_difference.h"
#include "model/tire/tmeasy_tire.h"
#include "model/vehicle/suspension_kinematics.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/driver_inputs.h"
#include "tests/support/steering_axis_off.h"

namespace rig::model::vehicle {
namespace {

VehicleParams sedan() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
}

Signals driver_inputs() { return test::all_driver_inputs(); }

/// A McPherson-like front and multi-link-like rear: recession, scrub, camber gain, toe.
VehicleParams sedan_with_geometry() {
  VehicleParams p = sedan();
  for (AxleParams& a : p.axles) {
    a.kinematics.x_per_travel = -0.05;
    a.kinematics.track_per_travel = 0.08;
    a.kinematics.track_per_travel2_per_m = -0.6;
    a.kinematics.camber_per_travel_radpm = 0.35;  // left wheel: alpha grows with bump
  }
  return p;
}

TEST(SuspensionKinematics, RightWheelIsTheMirrorImageOfTheLeft) {
  VehicleParams p = sedan_with_geometry();
  p.axles[0].kinematics.toe_rad = 0.002;
  p.axles[0].kinematics.bump_steer_radpm = 0.05;
  const SuspensionKinematics k(p);
  const double arm = p.steering.steering_arm_m;
  for (const double z : {-0.06, -0.01, 0.0, 0.03, 0.07}) {
    for (const double u : {-0.03, 0.0, 0.011}) {
      const auto l = k.pose(0, z, u), r = k.pose(1, z, -u);
      EXPECT_NEAR(r.x_m.value, l.x_m.value, 1e-12);
      EXPECT_NEAR(r.y_m.value, -l.y_m.value, 1e-12);
      EXPECT_NEAR(r.alpha_rad.value, -l.alpha_rad.value, 1e-12);
      EXPECT_NEAR(r.gamma_rad.value, -l.gamma_rad.value, 1e-12);
      // the generated tables reproduce the geometry (bicubic on 1 cm / 21 rack nodes)
      const double steer = std::asin(u / arm);
      EXPECT_NEAR(l.gamma_rad.value, 0.002 + 0.05 * z + steer, 2e-5) << z << " " << u;
      EXPECT_NEAR(l.gamma_rad.d_du, 1.0 / (arm * std::cos(steer)), 0.01 / arm);
      EXPECT_NEAR(l.y_m.value, 0.08 * z - 0.6 * z * z, 1e-9);
      EXPECT_NEAR(l.y_m.d_dz, 0.08 - 1.2 * z, 1e-6);
      EXPECT_NEAR(l.x_m.d_dz, -0.05, 1e-9);
    }
  }
  // an unsteered axle ignores the rack
  EXPECT_EQ(k.pose(2, 0.02, 0.05).gamma_rad.value, 0.0);
}

TEST(SuspensionKinematics, GivenTablesAreUsedAndCheckedAtConstruction) {
  VehicleParams p = sedan();
  AxleKinematicsParams& k = p.axles[1].kinematics;
  k.grid = {-0.1, 0.1, 3, 0.0, 1.0, 1};  // z in {-0.1, 0, 0.1}, no rack
  k.x_m = {0.002, 0.0, -0.002};
  k.y_m = {-0.004, 0.0, 0.004};
  k.alpha_rad = {-0.01, 0.0, 0.01};
  k.beta_rad = {0, 0, 0};
  k.gamma_rad = {0.001, 0.0, -0.001};
  k.bicubic = false;
  const SuspensionKinematics sk(p);
  EXPECT_NEAR(sk.pose(2, 0.05, 0).y_m.value, 0.002, 1e-12);
  EXPECT_NEAR(sk.pose(3, 0.05, 0).y_m.value, -0.002, 1e-12);
  EXPECT_NEAR(sk.pose(2, 0.05, 0).x_m.d_dz, -0.02, 1e-12);
  EXPECT_NEAR(sk.pose(3, -0.1, 0).alpha_rad.value, 0.01, 1e-12);
  k.gamma_rad.pop_back();
  EXPECT_THROW(SuspensionKinematics{p}, std::invalid_argument);
  k.gamma_rad.push_back(0.0);
  k.grid = {-0.1, 0.1, 3, 0.0, 0.01, 1};
  p.axles[0].kinematics = k;
  p.axles[0].kinematics.grid = {-0.1, 0.1, 3, 0.0, 0.01, 1};
  p.axles[0].kinematics.grid.u_count = 1;
  EXPECT_NO_THROW(SuspensionKinematics{p});
  AxleKinematicsParams steered = k;
  steered.grid = {-0.1, 0.1, 3, -0.01, 0.01, 2};  // u in {-0.01, 0}: not symmetric
  steered.x_m = steered.y_m = steered.alpha_rad = steered.beta_rad = steered.gamma_rad =
      std::vector<double>(6, 0.0);
  p.axles[0].kinematics = steered;
  EXPECT_THROW(SuspensionKinematics{p}, std::invalid_argument);
}

/// The sedan file with `extra` appended to the rear axle's [axle.kinematics] table.
std::filesystem::path sedan_with_rear_kinematics(const std::string& extra) {
  std::ifstream in(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string key = "track_per_travel = 0.02\n";
  text.insert(text.rfind(key) + key.size(), extra);
  const auto file = std::filesystem::temp_directory_path() / "rig_kinematics_test.toml";
  std::ofstream(file) << text;
  return file;
}

TEST(SuspensionKinematics, VehicleFileReadsGeometryAndTables) {
  const VehicleParams p = sedan();
  EXPECT_DOUBLE_EQ(p.axles[0].kinematics.camber_per_travel_radpm, 0.35);
  EXPECT_DOUBLE_EQ(p.axles[0].kinematics.track_per_travel2_per_m, -0.5);
  EXPECT_TRUE(p.axles[0].kinematics.x_m.empty());  // generated
  const auto good = sedan_with_rear_kinematics(
      "grid = { z_min_m = -0.1, z_step_m = 0.1, z_count = 3, u_count = 1 }\n"
      "x_m = [0.0, 0.0, 0.0]\ny_m = [-0.004, 0.0, 0.004]\nalpha_rad = [0.0, 0.0, 0.0]\n"
      "beta_rad = [0.0, 0.0, 0.0]\ngamma_rad = [0.001, 0.0, -0.001]\n");
  const VehicleParams q = io::config::load_vehicle_file(good);
  ASSERT_EQ(q.axles[1].kinematics.y_m.size(), 3u);
  EXPECT_NEAR(SuspensionKinematics(q).pose(2, 0.05, 0).y_m.value, 0.002, 1e-12);
  const auto bad = sedan_with_rear_kinematics(
      "grid = { z_min_m = -0.1, z_step_m = 0.1, z_count = 3 }\n"
      "x_m = [0.0, 0.0]\ny_m = [0.0, 0.0, 0.0]\nalpha_rad = [0.0, 0.0, 0.0]\n"
      "beta_rad = [0.0, 0.0, 0.0]\ngamma_rad = [0.0, 0.0, 0.0]\n");
  try {
    (void)io::config::load_vehicle_file(bad);
    FAIL() << "no error";
  } catch (const io::config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("rig_kinematics_test.toml:"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("x_m"), std::string::npos) << e.what();
  }
  std::filesystem::remove(good);
  std::filesystem::remove(bad);
}

// Static toe-out on the front axle, driving straight at 20 m/s: each front tire runs at a slip
// angle equal to its steer angle (the toe less the tie-rod compliance steer), so
// F_y = dFy0(F_z) tan(steer), outwards on both sides, and the car still runs straight.
TEST(SuspensionKinematics, FrontToeGivesOpposedCorneringForces) {
  VehicleParams p = sedan();
  const double toe = 0.004;  // rad, front to the outside on both wheels (toe-out)
  p.axles[0].kinematics.toe_rad = toe;
  // the hand formula is the trails' alone: without the steering-axis geometry and bore torque
  // (issue 15; their straight-ahead moments, opposite left/right, add toe compliance)
  test::without_steering_axis(p.axles[0]);
  VehicleModel m(p, 1e-3);
  m.set_forward_speed(20);
  Signals s = driver_inputs();
  for (int k = 0; k < 3000; ++k) {
    s[Signal::kThrottlePedal] = std::clamp(0.25 + 0.5 * (20 - s[Signal::kVehicleSpeed]), 0.0, 1.0);
    ASSERT_EQ(m.step(s), StepStatus::kOk);
  }
  ModelReport r;
  m.fill_report(r);
  const auto& fl = r.units[0].wheels[0];
  const auto& fr = r.units[0].wheels[1];
  const double c_fl =
      tire::characteristic_at(p.axles[0].tire.tmeasy, fl.load_n, 1.0).y.initial_slope_n;
  const double c_fr =
      tire::characteristic_at(p.axles[0].tire.tmeasy, fr.load_n, 1.0).y.initial_slope_n;
  // the tie rods yield to the aligning torque F_y (n + caster trail): compliance steer
  // d gamma = -F_y (n + caster trail) (dgamma/du)^2 / c_tie, dgamma/du = 1/arm at small angles;
  // n is the tire's pneumatic trail at the wheel's logged state (the same on both sides here)
  const SteeringParams& st = p.steering;
  const tire::TireKinematics kin{fl.long_speed_mps, fl.lat_speed_mps, fl.spin_radps,
                                 fl.rolling_radius_m};
  const double trail_m =
      -tire::aligning_torque_nm(p.axles[0].tire.tmeasy, kin, fl.tire_load_n, 1.0) +
      p.axles[0].caster_trail_m;
  const double compliance =
      trail_m / (st.steering_arm_m * st.steering_arm_m * st.tie_rod_stiffness_npm);
  std::printf(
      "toe %.4f rad, trail %.4f m: steer FL %.5f rad (toe - compliance %.5f), F_y FL %.1f N "
      "(dFy0 tan(steer) %.1f), FR %.1f N (%.1f), yaw rate %.1e rad/s\n",
      toe, trail_m, fl.steer_angle_rad, toe - compliance * fl.force_y_n, fl.force_y_n,
      c_fl * std::tan(fl.steer_angle_rad), fr.force_y_n, c_fr * std::tan(fr.steer_angle_rad),
      s[Signal::kYawRate]);
  EXPECT_NEAR(fl.steer_angle_rad, toe - compliance * fl.force_y_n, 0.02 * toe);
  EXPECT_NEAR(fr.steer_angle_rad, -toe - compliance * fr.force_y_n, 0.02 * toe);
  EXPECT_GT(fl.force_y_n, 0.0);  // outwards on both sides
  EXPECT_NEAR(fl.force_y_n, c_fl * std::tan(fl.steer_angle_rad), 0.05 * c_fl * toe);
  EXPECT_NEAR(fr.force_y_n, c_fr * std::tan(fr.steer_angle_rad), 0.05 * c_fr * toe);
  EXPECT_LT(std::abs(s[Signal::kYawRate]), 1e-4);
  EXPECT_LT(std::abs(s[Signal::kPositionY]), 0.05);
}

struct Steady {
  double yaw_rate = 0, roll = 0, travel_fl = 0, travel_fr = 0;
};

Steady step_steer(const VehicleParams& p) {
  VehicleModel m(p, 1e-3);
  m.set_forward_speed(80 / 3.6);
  Signals s = driver_inputs();
  for (int k = 0; k < 5000; ++k) {
    s[Signal::kSteeringWheelAngleCmd] = m.time_s() > 1.0 ? 0.5 : 0.0;
    s[Signal::kThrottlePedal] =
        std::clamp(0.2 + 0.5 * (80 / 3.6 - s[Signal::kVehicleSpeed]), 0.0, 1.0);
    if (m.step(s) != StepStatus::kOk) return {NAN, NAN, NAN, NAN};
  }
  const auto& y = m.framework().coordinates();
  return {s[Signal::kYawRate], y(5), y(6), y(7)};
}

// Bump steer on the front axle (left wheel gamma = +k z, right wheel -k z: toe-out in bump)
// steers both front wheels out of a turn as the body rolls: roll understeer. The mean road-wheel
// angle changes by k (z_FL - z_FR) / 2 (< 0 in a left turn, where the right wheel is in bump);
// in the linear range the steady yaw rate scales with the effective road-wheel angle, so the
// ratio of the yaw rates is predicted from the measured hub travels.
TEST(SuspensionKinematics, FrontBumpSteerGivesRollUndersteer) {
  const VehicleParams base = sedan();
  VehicleParams bump = base;
  bump.axles[0].kinematics.bump_steer_radpm = 0.15;
  const Steady a = step_steer(base), b = step_steer(bump);
  ASSERT_TRUE(std::isfinite(a.yaw_rate) && std::isfinite(b.yaw_rate));
  const double delta =
      0.5 / (base.steering.steering_arm_m / base.steering.rack_per_pinion_m_per_rad);
  // left wheel: +k z_FL, right wheel (mirror): -k z_FR; mean road-wheel angle change:
  const double d_delta = 0.5 * 0.15 * (b.travel_fl - b.travel_fr);
  const double predicted = (delta + d_delta) / delta;
  const double measured = b.yaw_rate / a.yaw_rate;
  std::printf(
      "bump steer 0.15 rad/m: yaw rate %.4f -> %.4f rad/s (x%.3f), roll %.4f rad, "
      "travels FL/FR %.4f/%.4f m, predicted x%.3f\n",
      a.yaw_rate, b.yaw_rate, measured, b.roll, b.travel_fl, b.travel_fr, predicted);
  EXPECT_LT(measured, 0.99);  // less yaw: understeer
  EXPECT_NEAR(measured - 1.0, predicted - 1.0, 0.3 * std::abs(predicted - 1.0));
}

// With non-zero kinematics (recession, scrub, camber gain) the analytic partials of the hub
// block still match finite differences of q (the framework's stiff blocks).
TEST(SuspensionKinematics, FrameworkJacobiansMatchFiniteDifferencesWithGeometry) {
  Eigen::internal::set_is_malloc_allowed(true);
  VehicleModel m(sedan_with_geometry(), 1e-3);
  Signals s = driver_inputs();
  m.set_forward_speed(15);
  for (int k = 0; k < 2000; ++k) {
    s[Signal::kSteeringWheelAngleCmd] = 0.6;
    s[Signal::kThrottlePedal] = 0.3;
    ASSERT_EQ(m.step(s), StepStatus::kOk);
  }
  auto& fw = m.framework();
  const Eigen::Index n = fw.size();
  Eigen::MatrixXd ay(n, n), az(n, n), fy(n, n), fz(n, n);
  Eigen::VectorXd wy(n), wz(n), q0(n), q1(n);
  ASSERT_TRUE(fw.force_jacobians(fw.coordinates(), fw.speeds(), ay, az));
  solver::finite_difference_force_jacobians<Eigen::Dynamic>(fw, fw.coordinates(), fw.speeds(), fy,
                                                            fz, wy, wz, q0, q1);
  const auto hub = [&](const Eigen::MatrixXd& x) { return x.bottomRightCorner(n - 6, n - 6); };
  EXPECT_LT((hub(ay) - hub(fy)).norm(), 2e-3 * hub(fy).norm()) << hub(ay) << "\n" << hub(fy);
  EXPECT_LT((hub(az) - hub(fz)).norm(), 2e-2 * hub(fz).norm()) << hub(az) << "\n" << hub(fz);
  EXPECT_NEAR(ay(2, 2), fy(2, 2), 2e-3 * std::abs(fy(2, 2)));
  // the hub travel moves the centre outwards (scrub): a camber/scrub geometry is really active
  EXPECT_GT(std::abs(m.workspace().wheels[0].hub_dy_ds), 0.05);
}

}  // namespace
}  // namespace rig::model::vehicle
