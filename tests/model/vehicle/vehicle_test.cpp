// Acceptance tests of the generic vehicle (issue 6) on the sedan of config/vehicles/sedan.toml.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/tire/tmeasy_tire.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/driver_inputs.h"
#include "tests/support/fd_jacobians.h"
#include "tests/support/step_steer.h"

namespace rig::model::vehicle {
namespace {

VehicleParams sedan() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
}

Signals driver_inputs() { return test::all_driver_inputs(); }

/// Runs for `seconds`, calling `inputs(t, signals)` before each step; fails on a NaN.
void run(VehicleModel& m, Signals& s, double seconds,
         const std::function<void(double, Signals&)>& inputs) {
  const long n = std::lround(seconds / m.step_size_s());
  for (long k = 0; k < n; ++k) {
    if (inputs) inputs(m.time_s(), s);
    ASSERT_EQ(m.step(s), StepStatus::kOk) << "t = " << m.time_s();
  }
}

TEST(Vehicle, StaticEquilibrium) {
  const VehicleParams p = sedan();
  VehicleModel m(p, 1e-3);
  Signals s = driver_inputs();
  s[Signal::kGearRequest] = 0;
  run(m, s, 3.0, nullptr);
  double total = 0, front = 0;
  for (int i = 0; i < 4; ++i) total += m.wheel_load_n(i);
  front = m.wheel_load_n(0) + m.wheel_load_n(1);
  const double mass = m.framework().total_mass_kg();
  EXPECT_NEAR(total, mass * 9.81, 0.005 * mass * 9.81);
  // front share from the CG position (sprung mass at x = 0, unsprung masses at the axles)
  const double l = p.axles[0].position_x_m - p.axles[1].position_x_m;
  const double front_expected = p.chassis.mass_kg * 9.81 * (-p.axles[1].position_x_m) / l +
                                2 * p.axles[0].unsprung_mass_kg * 9.81;
  EXPECT_NEAR(front / total, front_expected / (mass * 9.81),
              0.005 * front_expected / (mass * 9.81));
  std::printf("static: total %.1f N (m g %.1f N), front %.2f %% (CG %.2f %%)\n", total, mass * 9.81,
              100 * front / total, 100 * front_expected / (mass * 9.81));
}

TEST(Vehicle, GradeHoldCreepAndRollAwayAtOneAndTwoMilliseconds) {
  for (double h : {1e-3, 2e-3}) {
    VehicleParams p = sedan();
    p.road.grade = 0.20;  // 20 % uphill in +x
    VehicleModel m(p, h);
    Signals s = driver_inputs();
    s[Signal::kGearRequest] = 0;
    s[Signal::kBrakePressureFront] = 3e6;
    s[Signal::kBrakePressureRear] = 3e6;
    run(m, s, 1.0, nullptr);  // settle: tire deflections take up the slope force
    const double x0 = m.framework().coordinates()(0);
    run(m, s, 10.0, nullptr);
    const double creep = std::abs(m.framework().coordinates()(0) - x0);
    std::printf("h=%.0f ms grade 20 %%: creep over 10 s braked = %.3g mm\n", h * 1e3, creep * 1e3);
    EXPECT_LT(creep, 1e-3);
    s[Signal::kBrakePressureFront] = 0;
    s[Signal::kBrakePressureRear] = 0;
    run(m, s, 3.0, nullptr);
    const double rolled = m.framework().coordinates()(0) - x0;
    std::printf("grade 20 %%: released, rolled %.2f m in 3 s, speed %.2f m/s\n", rolled,
                m.framework().speeds()(0));
    EXPECT_LT(rolled, -1.0);  // rolls back downhill
  }
}

TEST(Vehicle, AccelerationAndCoastDown) {
  VehicleModel m(sedan(), 1e-3);
  Signals s = driver_inputs();
  s[Signal::kThrottlePedal] = 1.0;
  double t100 = -1;
  run(m, s, 15.0, [&](double t, Signals& sig) {
    if (t100 < 0 && sig[Signal::kVehicleSpeed] >= 100 / 3.6) t100 = t;
  });
  const double v15 = s[Signal::kVehicleSpeed];
  std::printf("full throttle: 0-100 km/h %.2f s, v(15 s) = %.1f km/h, gear %d, engine %.0f rad/s\n",
              t100, 3.6 * v15, static_cast<int>(s[Signal::kGear]), s[Signal::kEngineSpeed]);
  EXPECT_GT(t100, 5.0);  // 135 kW, 1500 kg: about 7-9 s
  EXPECT_LT(t100, 12.0);
  EXPECT_GE(s[Signal::kGear], 3);
  // coast-down in neutral: drag + rolling resistance against the (rotational) inertia
  s[Signal::kThrottlePedal] = 0;
  s[Signal::kGearRequest] = 0;
  const double v0 = s[Signal::kVehicleSpeed];
  run(m, s, 10.0, nullptr);
  const double v1 = s[Signal::kVehicleSpeed];
  const VehicleParams& p = m.params();
  const double mass =
      m.framework().total_mass_kg() + 4 * p.axles[0].tire.spin_inertia_kgm2 / (0.31 * 0.31);
  double v = v0;
  for (int k = 0; k < 10000; ++k) {  // the hand model, explicit Euler at 1 ms
    v -=
        1e-3 *
        (0.5 * 1.2 * p.chassis.drag_area_m2 * v * v + 0.01 * m.framework().total_mass_kg() * 9.81) /
        mass;
  }
  std::printf("coast-down: %.2f -> %.2f m/s in 10 s (hand model %.2f m/s)\n", v0, v1, v);
  EXPECT_NEAR(v0 - v1, v0 - v, 0.15 * (v0 - v));
}

/// Step steer (ISO 7401) at 80 km/h: returns yaw rate history stats.
struct StepResult {
  double yaw_rate_final = 0, yaw_rate_peak = 0, t90 = -1, ay_final = 0, yaw_rate_spread_end = 0;
};

StepResult step_steer(double h, double sw_angle_rad, const VehicleParams& params,
                      double speed_mps = 80 / 3.6) {
  StepResult r;
  const double t_step = 1.0;
  double rmin = 1e9, rmax = -1e9;
  std::vector<double> yaw;
  const auto record = [&](double t, const VehicleModel& /*m*/, const Signals& s) {
    yaw.push_back(s[Signal::kYawRate]);
    r.ay_final = s[Signal::kLateralAccel];
    if (t > 5.0) {
      rmin = std::min(rmin, s[Signal::kYawRate]);
      rmax = std::max(rmax, s[Signal::kYawRate]);
    }
  };
  // tests/support/step_steer.h: 6 s, the ramp from t_step, the throttle holding the speed
  if (!test::run_step_steer(params, h,
                            {.sw_rad = sw_angle_rad, .speed_mps = speed_mps, .t_step_s = t_step},
                            record)) {
    r.yaw_rate_final = NAN;
    return r;
  }
  r.yaw_rate_final = yaw.back();
  r.yaw_rate_spread_end = rmax - rmin;
  for (std::size_t k = 0; k < yaw.size(); ++k) {
    r.yaw_rate_peak = std::max(r.yaw_rate_peak, yaw[k]);
    if (r.t90 < 0 && yaw[k] >= 0.9 * r.yaw_rate_final)
      r.t90 = static_cast<double>(k + 1) * h - (t_step + 0.05);
  }
  return r;
}

TEST(Vehicle, StepSteerSettlesAtOneAndTwoMilliseconds) {
  for (double h : {1e-3, 2e-3}) {
    const StepResult r = step_steer(h, 0.5, sedan());  // ~29 deg at the steering wheel, ~4 m/s^2
    ASSERT_TRUE(std::isfinite(r.yaw_rate_final)) << "h = " << h;
    std::printf(
        "step steer h=%.0f ms: yaw rate %.4f rad/s, a_y %.2f m/s^2, response time (90 %%) %.3f s, "
        "overshoot %.1f %%, spread in the last second %.2e rad/s\n",
        h * 1e3, r.yaw_rate_final, r.ay_final, r.t90,
        100 * (r.yaw_rate_peak / r.yaw_rate_final - 1), r.yaw_rate_spread_end);
    EXPECT_GT(r.yaw_rate_final, 0.1);
    EXPECT_LT(r.t90, 0.5);
    EXPECT_LT(r.yaw_rate_peak / r.yaw_rate_final, 1.3);
    EXPECT_LT(r.yaw_rate_spread_end, 0.01 * r.yaw_rate_final);  // no (numerical) oscillation left
  }
}

TEST(Vehicle, DeterministicAndNoAllocationPerStep) {
  const VehicleParams p = sedan();
  VehicleModel a(p, 1e-3), b(p, 1e-3);
  Signals sa = driver_inputs(), sb = driver_inputs();
  const auto inputs = [](double t, Signals& s) {
    s[Signal::kThrottlePedal] = 0.5;
    s[Signal::kSteeringWheelAngleCmd] = 0.3 * std::sin(t);
    s[Signal::kBrakePressureFront] = t > 3 ? 2e6 : 0;
    s[Signal::kBrakePressureRear] = t > 3 ? 1e6 : 0;
  };
  run(a, sa, 0.5, inputs);  // first steps outside the counter (lazy one-time init of the library)
  run(b, sb, 0.5, inputs);
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  for (int k = 0; k < 4000; ++k) {
    inputs(a.time_s(), sa);
    inputs(b.time_s(), sb);
    ASSERT_EQ(a.step(sa), StepStatus::kOk);
    ASSERT_EQ(b.step(sb), StepStatus::kOk);
  }
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_EQ(sa.value, sb.value);  // bitwise
  ModelReport report;
  a.fill_report(report);
  EXPECT_EQ(report.units[0].wheel_count, 4);
}

TEST(Vehicle, SteadyStateCircleUndersteerGradientAndSaturation) {
  // ISO 4138, constant steering-wheel-angle method: steady states at discrete speeds (held by a
  // speed controller), then the speed raised slowly up to the limit.
  const VehicleParams p = sedan();
  VehicleModel m(p, 1e-3);
  Signals s = driver_inputs();
  const double sw = 1.1;  // rad at the steering wheel: R ~ 40 m at low speed
  const double l = p.axles[0].position_x_m - p.axles[1].position_x_m;
  double sxx = 0, sxy = 0, sx = 0, sy = 0, n = 0, ay_max = 0;
  double v_target = 3.0;
  m.set_forward_speed(v_target);
  const auto control = [&](double, Signals& sig) {
    sig[Signal::kSteeringWheelAngleCmd] = sw;
    sig[Signal::kThrottlePedal] =
        std::clamp(0.1 + 0.8 * (v_target - sig[Signal::kVehicleSpeed]), 0.0, 1.0);
  };
  s[Signal::kGearRequest] = 1;  // no shifts between the steady states
  for (double v_hold : {3.0, 4.0, 5.0, 6.0}) {
    v_target = v_hold;
    run(m, s, 8.0, control);
    const double v = s[Signal::kVehicleSpeed], r = s[Signal::kYawRate];
    const double ay = v * r;  // steady state: a_y = v^2 / R = v r
    const double steer =
        0.5 * (m.workspace().wheels[0].steer_rad + m.workspace().wheels[1].steer_rad);
    const double y = steer - l * r / v;  // delta - L / R = K a_y
    std::printf("circle v %.2f m/s: a_y %.3f m/s^2, delta - L/R = %.5f rad\n", v, ay, y);
    sxx += ay * ay, sxy += ay * y, sx += ay, sy += y, n += 1;
  }
  run(m, s, 58.0, [&](double t, Signals& sig) {
    v_target = 6.0 + 0.3 * (t - 32.0);
    sig[Signal::kGearRequest] = 99;
    control(t, sig);
    ay_max = std::max(ay_max, sig[Signal::kVehicleSpeed] * sig[Signal::kYawRate]);
  });
  const double k_measured = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  // linear single-track value from the model's own parameters: K = m_f / C_f - m_r / C_r with
  // C = 2 dF0_y(F_z) (TMeasy initial slope at the static wheel load) and the axle masses
  double cf = 0, cr = 0, fzf = 0, fzr = 0;
  {
    VehicleModel st(p, 1e-3);
    Signals s0 = driver_inputs();
    s0[Signal::kGearRequest] = 0;
    run(st, s0, 2.0, nullptr);
    fzf = st.wheel_load_n(0) + st.wheel_load_n(1);
    fzr = st.wheel_load_n(2) + st.wheel_load_n(3);
    cf = 2 * tire::characteristic_at(p.axles[0].tire.tmeasy, fzf / 2, 1.0).y.initial_slope_n;
    cr = 2 * tire::characteristic_at(p.axles[1].tire.tmeasy, fzr / 2, 1.0).y.initial_slope_n;
  }
  const double k_linear = fzf / 9.81 / cf - fzr / 9.81 / cr;
  std::printf(
      "circle: understeer gradient %.5f rad/(m/s^2) = %.3f deg/g at the wheels (linear %.5f), "
      "a_y max %.2f m/s^2 = %.2f mu g, %d samples\n",
      k_measured, k_measured * 9.81 * 180 / M_PI, k_linear, ay_max, ay_max / 9.81,
      static_cast<int>(n));
  EXPECT_NEAR(k_measured, k_linear, 0.15 * std::abs(k_linear));
  EXPECT_GT(ay_max, 0.75 * 9.81);
  EXPECT_LT(ay_max, 1.05 * 9.81);
}

TEST(Vehicle, AnalyticPartialJacobiansMatchFiniteDifferences) {
  Eigen::internal::set_is_malloc_allowed(true);
  VehicleModel m(sedan(), 1e-3);
  Signals s = driver_inputs();
  m.set_forward_speed(15);
  run(m, s, 2.0, [](double, Signals& sig) {
    sig[Signal::kSteeringWheelAngleCmd] = 0.6;
    sig[Signal::kThrottlePedal] = 0.3;
  });
  // framework: the stiff blocks (hub-hub: suspension + tire vertical; vertical and lateral
  // speed: tire damping paths) are the whole derivative there, so they must agree
  auto& fw = m.framework();
  const Eigen::Index n = fw.size();
  Eigen::MatrixXd ay(n, n), az(n, n), fy, fz;
  ASSERT_TRUE(fw.force_jacobians(fw.coordinates(), fw.speeds(), ay, az));
  test::fd_jacobians<Eigen::Dynamic>(fw, fw.coordinates(), fw.speeds(), fy, fz);
  const auto hub = [&](const Eigen::MatrixXd& x) { return x.bottomRightCorner(n - 6, n - 6); };
  // forward differences of the solver's step (sqrt(eps) max(1, |x|)): 6.8e-5 and 1.6e-5
  std::printf("hub partials vs forward differences: dq/dy %.2e, dq/dz %.2e\n",
              test::relative_error(hub(ay), hub(fy)), test::relative_error(hub(az), hub(fz)));
  EXPECT_LT((hub(ay) - hub(fy)).norm(), 5e-4 * hub(fy).norm()) << hub(ay) << "\n" << hub(fy);
  EXPECT_LT((hub(az) - hub(fz)).norm(), 2e-4 * hub(fz).norm()) << hub(az) << "\n" << hub(fz);
  EXPECT_NEAR(ay(2, 2), fy(2, 2), 1e-3 * std::abs(fy(2, 2)));  // heave stiffness of the tires
  EXPECT_NEAR(az(2, 2), fz(2, 2), 2e-2 * std::abs(fz(2, 2)));  // tire vertical damping
  // tire lateral damping paths: the analytic one is taken at fixed f (eq. 24); in this turn
  // (a_y ~ 5 m/s^2) df/ds adds ~10 %, which the FD sees
  EXPECT_NEAR(az(1, 1), fz(1, 1), 0.15 * std::abs(fz(1, 1)));
  // steering: the analytic Jacobian is complete
  const auto block = m.steering_block();
  SimpleSteering* const* simple = std::get_if<SimpleSteering*>(&block);
  ASSERT_NE(simple, nullptr);  // the sedan's [steering] model is the simple one
  SimpleSteering& st = **simple;
  Eigen::Matrix2d sy2, sz2;
  ASSERT_TRUE(st.force_jacobians(st.coordinates(), st.speeds(), sy2, sz2));
  Eigen::MatrixXd gy, gz;
  test::fd_jacobians<2>(st, st.coordinates(), st.speeds(), gy, gz);
  // complete and nearly linear: 2.1e-5 and 1e-7
  std::printf("simple steering vs forward differences: dq/dy %.2e, dq/dz %.2e\n",
              test::relative_error(sy2, gy), test::relative_error(sz2, gz));
  EXPECT_LT((Eigen::MatrixXd(sy2) - gy).norm(), 2e-4 * gy.norm()) << sy2 << "\n" << gy;
  EXPECT_LT((Eigen::MatrixXd(sz2) - gz).norm(), 1e-6 * gz.norm()) << sz2 << "\n" << gz;
}

TEST(Vehicle, TruckStaticEquilibriumAndGradeHoldAtOneAndTwoMilliseconds) {
  for (double h : {1e-3, 2e-3}) {
    VehicleParams p =
        io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/truck-3axle.toml");
    VehicleModel flat(p, h);
    Signals s = driver_inputs();
    s[Signal::kGearRequest] = 0;
    run(flat, s, 3.0, nullptr);
    double total = 0;
    for (int i = 0; i < 6; ++i) total += flat.wheel_load_n(i);
    const double mg = flat.framework().total_mass_kg() * 9.81;
    EXPECT_NEAR(total, mg, 0.005 * mg) << "h = " << h;
    p.road.grade = 0.2;
    VehicleModel hill(p, h);
    s[Signal::kBrakePressureFront] = 8e5;
    s[Signal::kBrakePressureRear] = 8e5;
    run(hill, s, 2.0, nullptr);
    const double x0 = hill.framework().coordinates()(0);
    run(hill, s, 10.0, nullptr);
    const double creep = std::abs(hill.framework().coordinates()(0) - x0);
    std::printf("truck h=%.0f ms: loads %.0f N (m g %.0f N), creep on 20 %% over 10 s %.3g mm\n",
                h * 1e3, total, mg, creep * 1e3);
    EXPECT_LT(creep, 1e-3);
  }
}

TEST(VehicleConfig, UnknownKeyIsAnErrorWithFileAndLine) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "rig_vehicle_config_test";
  std::filesystem::create_directories(dir);
  std::ifstream in(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto pos = text.find("cg_height_m");
  text.insert(pos, "cg_hieght_m = 0.5\n");
  const auto file = dir / "typo.toml";
  std::ofstream(file) << text;
  try {
    (void)io::config::load_vehicle_file(file);
    FAIL() << "no error";
  } catch (const io::config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("typo.toml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cg_hieght_m"), std::string::npos) << e.what();
  }
}

// Impossible vehicles (issue 13) are errors at load, with the line of the offending key.
TEST(VehicleConfig, ImpossibleVehiclesAreErrorsWithFileAndLine) {
  struct Mutation {
    std::string from, to, message;
  };
  const std::vector<Mutation> mutations = {
      {"[4.17, 2.34,", "[4.17, 0.0,", "gear_ratios: ratios must lie in [0.1, 50]"},
      {"[4.17, 2.34,", "[2.0, 2.34,", "fall strictly from first gear to top gear"},
      {"[150.0, 250.0,", "[150.0, -250.0,", "engine torques must lie in [0, 1e5] N m"},
      {"inertia_xx_kgm2 = 480.0", "inertia_xx_kgm2 = 4500.0", "no rigid body has these inertias"},
      {"inertia_xz_kgm2 = 0.0", "inertia_xz_kgm2 = 1100.0", "positive definite"},
      {"position_x_m = -1.60", "position_x_m = 1.20", "[[axle]] tables go from front to rear"},
      {"initial_slope_n = 55000.0", "initial_slope_n = 20000.0",
       "must exceed max_force_n / slip_at_max"},
      {"max_force_n = 7500.0, slip_at_max = 0.22, sliding_force_n = 7400.0",
       "max_force_n = 9000.0, slip_at_max = 0.22, sliding_force_n = 7400.0",
       "max_force_n must exceed that of [lateral_nominal] and be at most twice it"},
      {"downshift_speed_radps = 120.0", "downshift_speed_radps = 200.0",
       "must be below upshift_speed_low_radps"},
      {"upshift_speed_high_radps = 580.0", "upshift_speed_high_radps = 700.0",
       "must not exceed max_speed_radps"},
  };
  std::ifstream in(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  const std::string sedan((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto file = std::filesystem::temp_directory_path() / "rig_impossible_vehicle.toml";
  for (const auto& m : mutations) {
    std::string text = sedan;
    const auto pos = text.find(m.from);
    ASSERT_NE(pos, std::string::npos) << m.from;
    text.replace(pos, m.from.size(), m.to);
    const int line = static_cast<int>(std::count(text.begin(), text.begin() + pos, '\n')) + 1;
    std::ofstream(file) << text;
    try {
      (void)io::config::load_vehicle_file(file);
      ADD_FAILURE() << "no error for " << m.to;
    } catch (const io::config::ConfigError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file.string() + ":" + std::to_string(line) + ":", 0), 0u) << what;
      EXPECT_NE(what.find(m.message), std::string::npos) << what;
    }
  }
  std::filesystem::remove(file);
}

TEST(Vehicle, GradeBrakeToStandstillHoldAndDriveAway) {
  VehicleParams p = sedan();
  p.road.grade = 0.20;
  VehicleModel m(p, 1e-3);
  m.set_forward_speed(5.0);  // rolling uphill in D, then braked to stand-still
  Signals s = driver_inputs();
  s[Signal::kBrakePressureFront] = 3e6;
  s[Signal::kBrakePressureRear] = 1.5e6;
  run(m, s, 4.0, nullptr);
  EXPECT_NEAR(s[Signal::kVehicleSpeed], 0.0, 1e-3);
  const double x0 = s[Signal::kPositionX];
  run(m, s, 10.0, nullptr);
  const double creep = std::abs(s[Signal::kPositionX] - x0);
  s[Signal::kBrakePressureFront] = 0;
  s[Signal::kBrakePressureRear] = 0;
  s[Signal::kThrottlePedal] = 0.6;
  run(m, s, 5.0, nullptr);
  const double climbed = s[Signal::kPositionX] - x0;
  std::printf(
      "grade 20 %% in D: creep while held 10 s %.3g mm, drove %.2f m uphill in 5 s (%.1f km/h, "
      "gear %d)\n",
      creep * 1e3, climbed, 3.6 * s[Signal::kVehicleSpeed], static_cast<int>(s[Signal::kGear]));
  EXPECT_LT(creep, 1e-3);
  EXPECT_GT(climbed, 3.0);
}

/// Steady steering-wheel angle and torsion bar torque under a constant hand torque at 60 km/h.
std::pair<double, double> torque_steer(bool assist_from_can, double can_assist_nm) {
  VehicleParams p = sedan();
  p.steering.torque_input = true;
  p.steering.assist_from_input = assist_from_can;
  VehicleModel m(p, 1e-3);
  m.set_forward_speed(60 / 3.6);
  Signals s = driver_inputs();
  s[Signal::kGearRequest] = 3;
  s[Signal::kThrottlePedal] = 0.15;
  s[Signal::kSteeringWheelTorqueCmd] = 2.0;
  if (assist_from_can) s[Signal::kAssistTorque] = can_assist_nm;
  run(m, s, 4.0, nullptr);
  return {s[Signal::kSteeringWheelAngle], s[Signal::kTorsionBarTorque]};
}

TEST(Vehicle, SteeringByTorqueWithBoostCurveOrCanAssist) {
  const auto [angle_boost, tb_boost] = torque_steer(false, 0);
  const auto [angle_none, tb_none] = torque_steer(true, 0.0);  // ECU on CAN sends no assist
  std::printf(
      "hand torque 2 N m at 60 km/h: steering wheel %.3f rad with the boost curve, %.3f rad "
      "with CAN assist = 0 (torsion bar %.2f / %.2f N m)\n",
      angle_boost, angle_none, tb_boost, tb_none);
  // the torsion bar carries the hand torque in steady state (column inertia and damping at rest)
  EXPECT_NEAR(tb_boost, 2.0, 0.1);
  EXPECT_NEAR(tb_none, 2.0, 0.1);
  EXPECT_GT(angle_boost, 0.0);
  // assist multiplies the rack force the same hand torque can hold: much more steering angle
  EXPECT_GT(angle_boost, 2.0 * angle_none);
}

TEST(VehicleConfig, ManeuverFilesNameTheirVehicleAndRunAtOneMillisecond) {
  int files = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(RIG_SOURCE_DIR "/config/maneuvers")) {
    if (entry.path().extension() != ".toml") continue;
    const toml::table doc = io::config::load_toml_file(entry.path());
    io::config::StrictTable top(doc, entry.path(), "top level");
    io::config::StrictTable model_table = top.table("model");
    if (entry.path().filename() == "paper-quarter-car.toml") continue;  // the paper's example
    ++files;
    EXPECT_EQ(model_table.string("kind"), "vehicle") << entry.path();
    const auto settings = io::config::read_vehicle_model(model_table);
    model_table.finish();  // no unknown vehicle keys
    VehicleModel m(settings.params, 1e-3);
    m.set_forward_speed(settings.initial_speed_mps);
    Signals s = driver_inputs();
    run(m, s, 0.2, nullptr);
    EXPECT_NEAR(s[Signal::kVehicleSpeed], settings.initial_speed_mps, 0.5) << entry.path();
  }
  // + weave, parking effort (0 and 5 km/h), returnability (issue 15); + the Belgian block (sedan,
  // truck), sine-wave road, ISO 8608 class C, cleat, mu-jump and mu-split braking (issue 16);
  // + braking 100-0 (issue 18); + the mu-split accelerations of the sedan-4x4 and the 6x4
  // tractor's differentials (issue 17 item 6), the tractor with cab, engine and seat (item 4), the
  // truck on rigid axles (items 1, 3), the frame-torsion tractor's circle (item 5), the
  // leaf-sprung van's braking (leaf axle), the leaf-sprung tractor's braking (item 7)
  EXPECT_EQ(files, 24);
}

TEST(Vehicle, TruckStepSteerSettlesAtOneAndTwoMilliseconds) {
  const VehicleParams p =
      io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/truck-3axle.toml");
  for (double h : {1e-3, 2e-3}) {
    const StepResult r = step_steer(h, 1.0, p, 60 / 3.6);
    ASSERT_TRUE(std::isfinite(r.yaw_rate_final)) << "h = " << h;
    std::printf(
        "truck step steer h=%.0f ms at 60 km/h: yaw rate %.4f rad/s, a_y %.2f m/s^2, response time "
        "%.3f s, "
        "overshoot %.1f %%\n",
        h * 1e3, r.yaw_rate_final, r.ay_final, r.t90,
        100 * (r.yaw_rate_peak / r.yaw_rate_final - 1));
    EXPECT_GT(r.yaw_rate_final, 0.05);
    EXPECT_LT(r.yaw_rate_spread_end, 0.01 * r.yaw_rate_final);
  }
}

}  // namespace
}  // namespace rig::model::vehicle
