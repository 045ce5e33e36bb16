// Acceptance tests of vehicle combinations as index-3 DAEs (issue 7) on
// config/combinations/car-trailer.toml and tractor-semitrailer.toml.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/combination/combination.h"
#include "model/combination/force_coupled.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/combination_files.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::combination {
namespace {

using test::kCarTowBarCar;
using test::kCarTrailer;
using test::kTractorSemi;

CombinationParams load(const char* file) { return test::load_combination(file); }

Signals driver_inputs() { return test::all_driver_inputs(); }

TEST(CombinationConfig, MissingJointIsAnErrorWithFileAndLine) {
  const std::string file = ::testing::TempDir() + "/combination-missing-joint.toml";
  {
    FILE* f = std::fopen(file.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fprintf(f,
                 "[model]\nkind = \"combination\"\n[[model.unit]]\nvehicle = "
                 "\"%s/config/vehicles/sedan.toml\"\n[[model.unit]]\nvehicle = "
                 "\"%s/config/vehicles/trailer-1axle.toml\"\n",
                 RIG_SOURCE_DIR, RIG_SOURCE_DIR);
    std::fclose(f);
  }
  try {
    (void)load(file.c_str());
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file), std::string::npos) << what;
    EXPECT_NE(what.find("joint"), std::string::npos) << what;
  }
}

TEST(Joint, PartialDerivativesMatchFiniteDifferences) {
  for (const JointKind kind : {JointKind::kBall, JointKind::kFifthWheel}) {
    JointParams p;
    p.kind = kind;
    p.leading_point_m = Vec3(-1.9, 0.05, 0.1);
    p.trailing_point_m = Vec3(4.8, -0.02, -0.6);
    const Joint j(p);
    Eigen::VectorXd ya(6), yb(6);
    ya << 10, 2, 1.1, 0.3, 0.02, -0.03;
    yb << 3.5, -1, 1.8, -0.2, -0.015, 0.04;
    JointEvaluation e, e1;
    j.evaluate(ya, yb, e);
    const double eps = 1e-7;
    double worst = 0;
    for (int c = 0; c < 6; ++c) {
      Eigen::VectorXd a = ya, b = yb;
      a(c) += eps;
      j.evaluate(a, yb, e1);
      worst = std::max(worst,
                       ((e1.g - e.g) / eps - e.dg_dya.col(c)).head(j.size()).cwiseAbs().maxCoeff());
      b(c) += eps;
      j.evaluate(ya, b, e1);
      worst = std::max(worst,
                       ((e1.g - e.g) / eps - e.dg_dyb.col(c)).head(j.size()).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-5) << (kind == JointKind::kBall ? "ball" : "fifth wheel");
  }
}

TEST(Combination, StaticHitchLoadAndNoDrift) {
  for (const char* file : {kCarTrailer, kTractorSemi}) {
    Combination c(load(file), 1e-3);
    Signals s = driver_inputs();
    s[Signal::kGearRequest] = 0;
    double max_g = 0;
    for (int k = 0; k < 2000; ++k) {
      ASSERT_EQ(c.step(s), StepStatus::kOk);
      max_g = std::max(max_g, c.joint_violation_m(0));
    }
    const double expected = c.unit(1).framework().support_load_n();
    const Vec3 f = c.joint_force_n(0);
    std::printf(
        "%s standing: joint force on the leading unit (%.1f, %.1f, %.1f) N, static "
        "support load %.1f N, max |g| %.2g m\n",
        file, f.x(), f.y(), f.z(), expected, max_g);
    EXPECT_NEAR(-f.z(), expected, 0.02 * expected + 5);
    EXPECT_LT(std::abs(f.x()), 0.01 * expected + 5);
    EXPECT_LT(max_g, 1e-6);
  }
}

// Start in equilibrium (issue 12, part 4) for combinations: at rest with zero inputs, and at a
// speed with the throttle settle() reports, every unit's |a_x - a_x,steady| and |a_z| stay below
// 0.05 m/s^2 over the first second; without settle() the start transient is far larger.
struct FirstSecond {
  double ax_dev = 0, az = 0, joint = 0;  // over all units; joint: max |g| [m]
};
FirstSecond first_second(Combination& c, Signals s) {
  FirstSecond f;
  while (c.time_s() < 1.0 - 1e-9) {
    EXPECT_EQ(c.step(s), StepStatus::kOk);
    for (int u = 0; u < c.unit_count(); ++u) {
      const Vec3& a = c.unit(u).state().acceleration_mps2;
      f.ax_dev = std::max(f.ax_dev, std::abs(a.x()));
      f.az = std::max(f.az, std::abs(a.z()));
    }
    f.joint = std::max(f.joint, c.joint_violation_m(0));
  }
  return f;
}

TEST(Combination, StartsInEquilibriumAtRestAndAtSpeed) {
  for (const char* file : {kCarTrailer, kTractorSemi}) {
    for (double v : {0.0, 20.0}) {
      Combination raw(load(file), 1e-3);
      Combination c(load(file), 1e-3);
      Signals s = driver_inputs();
      s[Signal::kGearRequest] = v == 0 ? 0 : 99;
      if (v != 0) raw.set_forward_speed(v);
      const vehicle::Equilibrium e = c.settle(v);
      EXPECT_EQ(c.time_s(), 0.0);
      EXPECT_NEAR(c.unit(1).state().framework_z(0), v, 1e-12);
      s[Signal::kThrottlePedal] = e.throttle;
      const FirstSecond before = first_second(raw, s);
      const FirstSecond after = first_second(c, s);
      std::printf(
          "%s at %.0f m/s: throttle %.3f (gear %d, a_x left %.4f); first second |a_x| %.4f, "
          "|a_z| %.4f m/s^2, |g| %.1e m (without settle: %.3f, %.3f)\n",
          file, v, e.throttle, e.gear, e.residual_ax_mps2, after.ax_dev, after.az, after.joint,
          before.ax_dev, before.az);
      if (v != 0) {
        EXPECT_GT(e.throttle, 0.0);
      }
      EXPECT_LT(std::abs(e.residual_ax_mps2), 0.01);
      EXPECT_LT(after.ax_dev, 0.05);
      EXPECT_LT(after.az, 0.05);
      EXPECT_LT(after.joint, 1e-6);
      EXPECT_NEAR(c.unit(0).state().framework_z(0), v, 0.05 + 0.01 * v);
    }
  }
}

TEST(Combination, LowSpeedCircleArticulationMatchesKinematicEstimate) {
  // Steady circle at 2 m/s (a_y < 0.3 m/s^2: tire slip angles ~0.2 deg): the articulation angle
  // against the kinematic estimate from the hitch offset c behind the car's rear axle and the
  // trailer's hitch-to-axle length l, with R the radius of the car's rear axle centre:
  //   Gamma = atan(c / R) + atan(l / sqrt(R^2 + c^2 - l^2)).
  const CombinationParams p = load(kCarTrailer);
  for (const double wheel_angle_rad : {1.6, 3.2}) {
    Combination c(p, 1e-3);
    Signals s = driver_inputs();
    const double v_target = 2.0;
    c.set_forward_speed(v_target);
    const long n = 60000;
    for (long k = 0; k < n; ++k) {
      const double v = c.unit(0).speeds()(0);
      s[Signal::kThrottlePedal] = std::clamp(0.08 + 0.5 * (v_target - v), 0.0, 1.0);
      s[Signal::kSteeringWheelAngleCmd] = std::min(1.0, c.time_s() / 2.0) * wheel_angle_rad;
      ASSERT_EQ(c.step(s), StepStatus::kOk);
    }
    const auto& z = c.unit(0).speeds();
    const double x_rear = p.units[0].axles[1].position_x_m;
    const double yaw_rate = z(5);
    const double v_rear = z(0);  // omega x r adds only lateral/vertical terms at the axle centre
    const double radius = v_rear / yaw_rate;
    const double hitch_offset = x_rear - p.joints[0].leading_point_m.x();
    const double trailer_length =
        p.joints[0].trailing_point_m.x() - p.units[1].axles[0].position_x_m;
    const double kinematic =
        std::atan(hitch_offset / radius) +
        std::atan(trailer_length / std::sqrt(radius * radius + hitch_offset * hitch_offset -
                                             trailer_length * trailer_length));
    const double measured = c.articulation_rad(0);
    std::printf(
        "circle: R = %.2f m (rear axle), articulation %.4f rad, kinematic %.4f rad "
        "(%.2f %%), lateral slip of the rear axle %.4f m/s\n",
        radius, measured, kinematic, 100 * (measured - kinematic) / kinematic,
        z(1) + yaw_rate * x_rear);
    EXPECT_NEAR(measured, kinematic, 0.05 * kinematic);
  }
}

TEST(Combination, SplitMuBrakingJackknifeTendencyWithoutBreakdown) {
  // Straight-line braking on split mu (left wheels mu = 1.0, right wheels 0.2), steering wheel
  // held straight (no driver correction, no ABS, the low-mu wheels lock): the brake forces on
  // the left yaw the tractor to the left (+yaw) and the trailer swings out against it - with
  // these inputs the combination jackknifes completely (there is no contact model between the
  // units, so the articulation may pass 90 deg). Writes the history as CSV
  // (RIG_SPLIT_MU_CSV=dir). Asserts: the yaw goes to the high-mu side, the articulation grows
  // past 0.3 rad, no numerical breakdown (finite, |g| < 0.1 mm, <= 2 Newton iterations) and the
  // same motion at h = 1 and 2 ms (max articulation within 5 %).
  struct Case {
    const char* file;
    double speed_mps, front_pa, rear_pa, seconds;
  };
  std::vector<double> articulation_by_run;
  for (const double h : {1e-3, 2e-3}) {
    for (const Case& k : {Case{kCarTrailer, 80 / 3.6, 6e6, 3e6, 6.0},
                          Case{kTractorSemi, 60 / 3.6, 6e5, 6e5, 8.0}}) {
      CombinationParams p = load(k.file);
      for (auto& u : p.units) {
        u.road.friction = 1.0;
        u.road.friction_right = 0.2;
      }
      Combination c(p, h);
      c.set_forward_speed(k.speed_mps);
      Signals s = driver_inputs();
      s[Signal::kGearRequest] = 0;
      double max_articulation = 0, max_g = 0, max_yaw = 0, first_yaw = 0;
      int max_it = 0;
      const char* dir = std::getenv("RIG_SPLIT_MU_CSV");
      FILE* csv = nullptr;
      if (dir != nullptr && h == 1e-3) {
        const std::string name =
            std::string(dir) + "/split-mu-" +
            (k.file == std::string(kCarTrailer) ? "car-trailer" : "tractor-semitrailer") + ".csv";
        csv = std::fopen(name.c_str(), "w");
        if (csv != nullptr)
          std::fprintf(csv, "t_s,x_m,y_m,yaw_rad,articulation_rad,speed_mps,fx_n,fy_n,fz_n\n");
      }
      const long n = std::lround(k.seconds / h);
      for (long step = 0; step < n; ++step) {
        const double ramp = std::min(1.0, c.time_s() / 0.3);
        s[Signal::kThrottlePedal] = 0;
        s[Signal::kBrakePressureFront] = ramp * k.front_pa;
        s[Signal::kBrakePressureRear] = ramp * k.rear_pa;
        ASSERT_EQ(c.step(s), StepStatus::kOk) << k.file << " t = " << c.time_s();
        max_articulation = std::max(max_articulation, std::abs(c.articulation_rad(0)));
        max_yaw = std::max(max_yaw, std::abs(c.unit(0).coordinates()(3)));
        if (first_yaw == 0 && std::abs(c.unit(0).coordinates()(3)) > 0.01)
          first_yaw = c.unit(0).coordinates()(3);
        max_g = std::max(max_g, c.joint_violation_m(0));
        max_it = std::max(max_it, c.last_newton().iterations);
        if (csv != nullptr && step % 10 == 0) {
          const Vec3 f = c.joint_force_n(0);
          const auto& y = c.unit(0).coordinates();
          std::fprintf(csv, "%.3f,%.4f,%.4f,%.5f,%.5f,%.4f,%.1f,%.1f,%.1f\n", c.time_s(), y(0),
                       y(1), y(3), c.articulation_rad(0), c.unit(0).speeds()(0), f.x(), f.y(),
                       f.z());
        }
      }
      if (csv != nullptr) std::fclose(csv);
      std::printf(
          "split mu h = %.0f ms %s: tractor yaw %.1f deg, max articulation %.1f deg, "
          "speed at end %.2f m/s, max |g| %.2g m, max Newton iterations %d\n",
          h * 1e3, k.file, max_yaw * 180 / std::numbers::pi,
          max_articulation * 180 / std::numbers::pi, c.unit(0).speeds()(0), max_g, max_it);
      EXPECT_GT(first_yaw, 0.0);  // towards the high-mu (left) side
      EXPECT_GT(max_articulation, 0.3);
      EXPECT_LT(max_g, 1e-4);
      EXPECT_LE(max_it, 2);
      articulation_by_run.push_back(max_articulation);
    }
  }
  ASSERT_EQ(articulation_by_run.size(), 4u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(articulation_by_run[i + 2], articulation_by_run[i],
                0.05 * articulation_by_run[i]);  // h = 2 ms vs 1 ms
  }
}

// ---- car + tow bar + car (method.md sec. 5): one distance constraint ----

TEST(Joint, TowBarPartialDerivativesMatchFiniteDifferences) {
  JointParams p;
  p.kind = JointKind::kTowBar;
  p.leading_point_m = Vec3(-2.6, 0.05, -0.1);
  p.trailing_point_m = Vec3(2.1, -0.02, -0.1);
  p.length_m = 1.5;
  const Joint j(p);
  ASSERT_EQ(j.size(), 1);
  Eigen::VectorXd ya(6), yb(6);
  ya << 10, 2, 0.55, 0.3, 0.02, -0.03;
  yb << 5.2, 0.4, 0.6, 0.1, -0.015, 0.04;  // rod not along either car, not level
  JointEvaluation e, e1;
  j.evaluate(ya, yb, e);
  const double eps = 1e-7;
  double worst = 0;
  for (int c = 0; c < 6; ++c) {
    Eigen::VectorXd a = ya, b = yb;
    a(c) += eps;
    j.evaluate(a, yb, e1);
    worst = std::max(worst, std::abs((e1.g(0) - e.g(0)) / eps - e.dg_dya(0, c)));
    b(c) += eps;
    j.evaluate(ya, b, e1);
    worst = std::max(worst, std::abs((e1.g(0) - e.g(0)) / eps - e.dg_dyb(0, c)));
  }
  std::printf("tow bar: g = %.4f m, max |dg/dy - FD| = %.2g\n", e.g(0), worst);
  EXPECT_LT(worst, 1e-5);
  // g itself: |r_b + R_b p_b - r_a - R_a p_a| - L
  JointParams ball = p;
  ball.kind = JointKind::kBall;
  JointEvaluation eb;
  Joint(ball).evaluate(ya, yb, eb);
  EXPECT_NEAR(e.g(0), eb.g.head<3>().norm() - p.length_m, 1e-14);
}

/// Straight towing with the leading car's throttle on a PI speed control at `speed`, then the
/// leading car brakes from `brake_time`. RIG_TOW_TRACE=1 prints speeds and rod force every 0.25 s.
struct TowRun {
  double max_violation_m = 0;
  int max_iterations = 0;
  std::array<long, 12> iteration_histogram{};
  long steps = 0;
  bool finite = true;
  double towing_rod_force_n = 0;  ///< mean over the last 2 s before braking
  double towing_speed_mps = 0;    ///< the towed car's, mean over the same 2 s
  double towing_accel_mps2 = 0;   ///< the towed car's speed change over those 2 s, per second
  double min_rod_force_n = 0;     ///< while braking (most compressive)
  double max_rod_force_n = 0;     ///< peak tension over the whole run
};

TowRun tow_and_brake(Combination& c, double speed_mps, double brake_time_s, double seconds) {
  c.reset(0, 0, 0);
  c.set_forward_speed(speed_mps);
  Signals s = driver_inputs();
  TowRun r;
  double integral = 0, sum_f = 0, sum_v = 0, v_start = 0, v_end = 0;
  long n_avg = 0;
  const double h = c.step_size_s();
  const long n = std::lround(seconds / h);
  for (long k = 0; k < n; ++k) {
    const double t = c.time_s();
    const double v = c.unit(0).speeds()(0);
    if (t < brake_time_s) {  // PI speed control of the leading car
      const double e = speed_mps - v;
      integral += e * h;
      s[Signal::kThrottlePedal] = std::clamp(0.25 + 1.0 * e + 0.5 * integral, 0.0, 1.0);
      s[Signal::kBrakePressureFront] = 0;
      s[Signal::kBrakePressureRear] = 0;
    } else {  // the leading car brakes (the towed car's brakes are off), ramp 0.3 s
      const double ramp = std::min((t - brake_time_s) / 0.3, 1.0);
      s[Signal::kThrottlePedal] = 0;
      s[Signal::kBrakePressureFront] = 3e6 * ramp;
      s[Signal::kBrakePressureRear] = 1.5e6 * ramp;
    }
    if (c.step(s) != StepStatus::kOk) {
      r.finite = false;
      return r;
    }
    const int it = c.last_newton().iterations;
    r.max_iterations = std::max(r.max_iterations, it);
    ++r.iteration_histogram[static_cast<std::size_t>(std::min(it, 11))];
    r.max_violation_m = std::max(r.max_violation_m, c.joint_violation_m(0));
    ++r.steps;
    const double f = c.rod_force_n(0);
    if (std::getenv("RIG_TOW_TRACE") != nullptr && k % 250 == 0)
      std::printf("t %.2f v0 %.4f v1 %.4f F %.1f thr %.3f\n", c.time_s(), c.unit(0).speeds()(0),
                  c.unit(1).speeds()(0), f, s[Signal::kThrottlePedal]);
    if (!std::isfinite(f)) r.finite = false;
    r.max_rod_force_n = std::max(r.max_rod_force_n, f);
    if (c.time_s() > brake_time_s) r.min_rod_force_n = std::min(r.min_rod_force_n, f);
    if (c.time_s() > brake_time_s - 2.0 && c.time_s() <= brake_time_s) {
      if (n_avg == 0) v_start = c.unit(1).speeds()(0);
      v_end = c.unit(1).speeds()(0);
      sum_f += f;
      sum_v += v_end;
      ++n_avg;
    }
  }
  if (n_avg > 0) {
    r.towing_rod_force_n = sum_f / static_cast<double>(n_avg);
    r.towing_speed_mps = sum_v / static_cast<double>(n_avg);
    r.towing_accel_mps2 = (v_end - v_start) / (static_cast<double>(n_avg) * h);
  }
  return r;
}

TEST(Combination, CarTowBarCarStraightTowingThenBraking) {
  // Straight towing at 15 m/s, then the leading car brakes. The towed car is guided by its own
  // tires only (wheels straight, no driver): a single distance constraint leaves its yaw free,
  // so a straight run is the meaningful case.
  Combination c(load(kCarTowBarCar), 1e-3);
  ASSERT_EQ(c.constraint().size(), 1);
  const TowRun r = tow_and_brake(c, 15.0, 12.0, 15.0);
  // the expectation from the towed car's parameters: sum of f_r F_z over its wheels (F_z = its
  // weight: the rod is level and pinned, it carries no vertical load) + aero drag
  const vehicle::VehicleParams& towed = c.unit(1).params();
  double mass = towed.chassis.mass_kg, rolling = 0;
  for (const auto& a : towed.axles) {
    mass += 2 * a.unsprung_mass_kg;
    rolling += 2 * a.unsprung_mass_kg * a.tire.tmeasy.rolling_resistance;
  }
  rolling +=
      towed.chassis.mass_kg * towed.axles[0].tire.tmeasy.rolling_resistance;  // all tires equal
  rolling *= towed.road.gravity_mps2;
  const double v = r.towing_speed_mps;
  const double drag = 0.5 * towed.chassis.air_density_kgpm3 * towed.chassis.drag_area_m2 * v * v;
  const double expected = rolling + drag;
  std::printf(
      "car + tow bar + car, h = 1 ms: %ld steps, max |g| %.3g m, max Newton iterations %d "
      "(1: %ld, 2: %ld); steady towing at %.3f m/s (towed car dv/dt %.2g m/s^2): rod force %.1f N, "
      "expected f_r m g + drag = %.1f + %.1f = %.1f N (%+.2f %%); m a correction %.1f N; braking: "
      "min rod force %.1f N (compression), peak tension %.1f N\n",
      r.steps, r.max_violation_m, r.max_iterations, r.iteration_histogram[1],
      r.iteration_histogram[2], v, r.towing_accel_mps2, r.towing_rod_force_n, rolling, drag,
      expected, 100 * (r.towing_rod_force_n - expected) / expected, mass * r.towing_accel_mps2,
      r.min_rod_force_n, r.max_rod_force_n);
  EXPECT_TRUE(r.finite);
  EXPECT_LT(r.max_violation_m, 1e-4);
  EXPECT_LE(r.max_iterations, 2);
  EXPECT_NEAR(v, 15.0, 0.2);
  EXPECT_LT(std::abs(r.towing_accel_mps2), 0.005);  // constant speed: m a below 7.5 N
  EXPECT_NEAR(r.towing_rod_force_n, expected, 0.03 * expected);
  EXPECT_LT(r.min_rod_force_n, -1000.0);  // braking: the towed car pushes, rod in compression
  // the joint report: the rod force and the force on the leading car along the rod
  ModelReport report;
  c.fill_report(report);
  EXPECT_EQ(report.joint_count, 1);
  EXPECT_DOUBLE_EQ(report.joints[0].rod_force_n, c.rod_force_n(0));
  const Vec3 f = c.joint_force_n(0);
  EXPECT_NEAR(f.norm(), std::abs(c.rod_force_n(0)), 1e-9 * (1 + f.norm()));
}

TEST(Combination, CarTowBarCarNoNaNAtOneAndTwoMilliseconds) {
  for (const double h : {1e-3, 2e-3}) {
    Combination c(load(kCarTowBarCar), h);
    const TowRun r = tow_and_brake(c, 15.0, 6.0, 10.0);
    std::printf(
        "car + tow bar + car, h = %.0f ms: %ld steps, max |g| %.3g m, max Newton iterations %d, "
        "towing rod force %.1f N, min %.1f N\n",
        h * 1e3, r.steps, r.max_violation_m, r.max_iterations, r.towing_rod_force_n,
        r.min_rod_force_n);
    EXPECT_TRUE(r.finite);
    EXPECT_LT(r.max_violation_m, 1e-4);
  }
}

TEST(Combination, CarTowBarCarNoStepAllocates) {
  Combination c(load(kCarTowBarCar), 1e-3);
  c.set_forward_speed(15);
  Signals s = driver_inputs();
  const auto inputs = [](double t, Signals& sig) {
    sig[Signal::kThrottlePedal] = t < 2 ? 0.15 : 0;
    sig[Signal::kBrakePressureFront] = t > 2 ? 3e6 : 0;
    sig[Signal::kBrakePressureRear] = t > 2 ? 1.5e6 : 0;
  };
  for (int k = 0; k < 200; ++k) {  // lazy one-time initializations outside the counter
    inputs(c.time_s(), s);
    ASSERT_EQ(c.step(s), StepStatus::kOk);
  }
  ModelReport report;
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  for (int k = 0; k < 3800; ++k) {
    inputs(c.time_s(), s);
    ASSERT_EQ(c.step(s), StepStatus::kOk);
    c.fill_report(report);
  }
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_EQ(report.unit_count, 2);
  EXPECT_EQ(report.joint_count, 1);
  EXPECT_LT(report.joints[0].violation_m, 1e-4);
}

}  // namespace
}  // namespace rig::model::combination
