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

#include "io/config/combination_file.h"
#include "io/config/strict_table.h"
#include "io/config/vehicle_file.h"
#include "model/combination/combination.h"
#include "model/combination/force_coupled.h"
#include "rig/driver/path_driver.h"
#include "rig/thread_begin_step_runner.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::combination {
namespace {

constexpr const char* kCarTrailer = RIG_SOURCE_DIR "/config/combinations/car-trailer.toml";
constexpr const char* kTractorSemi = RIG_SOURCE_DIR "/config/combinations/tractor-semitrailer.toml";
constexpr const char* kCarTowBarCar = RIG_SOURCE_DIR "/config/combinations/car-towbar-car.toml";

CombinationParams load(const char* file) {
  const toml::table doc = io::config::load_toml_file(file);
  io::config::StrictTable top(doc, file, "top level");
  io::config::StrictTable m = top.table("model");
  (void)m.string("kind");
  const io::config::CombinationModelSettings s = io::config::read_combination_model(m);
  CombinationParams p;
  p.name = s.name;
  p.units = s.units;
  p.joints = s.joints;
  p.parallel = s.parallel;
  p.newton = default_combination_newton_params();
  return p;
}

Signals driver_inputs() { return test::all_driver_inputs(); }

/// Steered by the leading unit: wheelbase and steering ratio for the path driver.
driver::PathDriverParams path_driver_for(const vehicle::VehicleParams& lead, double start_x_m,
                                         double speed_mps) {
  driver::PathDriverParams dp;
  dp.path = driver::iso3888_1_centreline(start_x_m);
  double rear = 0;
  int n = 0;
  for (const auto& a : lead.axles) {
    if (a.steered) continue;
    rear += a.position_x_m;
    ++n;
  }
  dp.wheelbase_m = lead.axles[0].position_x_m - rear / n;
  dp.steering_ratio = lead.steering.steering_arm_m / lead.steering.rack_per_pinion_m_per_rad;
  dp.target_speed_mps = speed_mps;
  dp.preview_time_s = lead.axles.size() > 2 ? 1.2 : 0.9;
  dp.preview_min_m = lead.axles.size() > 2 ? 10.0 : 6.0;
  return dp;
}

/// Statistics of a coupled run.
struct DriftStats {
  double max_violation_m = 0;
  int max_iterations = 0;
  std::array<long, 12> iteration_histogram{};
  long steps = 0;
  bool finite = true;
};

/// The path driver of the lane-change-and-brake runs: ISO 3888-1 from x = 30 m at `speed_mps`,
/// then the brakes ramped in 0.2 s to the given pressures from `brake_time_s`.
driver::PathDriverParams lane_change_then_brake(const vehicle::VehicleParams& lead,
                                                double speed_mps, double brake_time_s,
                                                double front_pa, double rear_pa) {
  driver::PathDriverParams dp = path_driver_for(lead, 30.0, speed_mps);
  dp.stop_time_s = brake_time_s;
  dp.stop_brake_pressure_front_pa = front_pa;
  dp.stop_brake_pressure_rear_pa = rear_pa;
  dp.stop_brake_ramp_s = 0.2;
  return dp;
}

/// Double lane change at `speed`, then hard braking (ramped to `brake_pa` on both circuits from
/// `brake_time`), on the combination; records |g| and Newton iterations every step.
DriftStats lane_change_and_brake(Combination& c, double speed_mps, double brake_time_s,
                                 double brake_front_pa, double brake_rear_pa, double seconds) {
  c.reset(0, 0, 0);
  c.set_forward_speed(speed_mps);
  driver::PathDriver d(lane_change_then_brake(c.unit(0).params(), speed_mps, brake_time_s,
                                              brake_front_pa, brake_rear_pa));
  Signals s = driver_inputs();
  DriftStats st;
  const long n = std::lround(seconds / c.step_size_s());
  for (long k = 0; k < n; ++k) {
    d.update(c.time_s(), s);
    if (c.step(s) != StepStatus::kOk) {
      st.finite = false;
      return st;
    }
    const int it = c.last_newton().iterations;
    st.max_iterations = std::max(st.max_iterations, it);
    ++st.iteration_histogram[static_cast<std::size_t>(std::min(it, 11))];
    for (int j = 0; j < c.constraint().joint_count(); ++j)
      st.max_violation_m = std::max(st.max_violation_m, c.joint_violation_m(j));
    ++st.steps;
  }
  return st;
}

void print_stats(const char* what, const DriftStats& st) {
  std::printf("%s: %ld steps, max |g| %.3g m, Newton iterations:", what, st.steps,
              st.max_violation_m);
  for (std::size_t i = 0; i < st.iteration_histogram.size(); ++i) {
    if (st.iteration_histogram[i] > 0)
      std::printf(
          " %zu: %ld (%.1f %%)", i, st.iteration_histogram[i],
          100.0 * static_cast<double>(st.iteration_histogram[i]) / static_cast<double>(st.steps));
  }
  std::printf("\n");
}

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

TEST(Combination, DriftBelowTenthMillimetreWithAtMostTwoNewtonIterations) {
  // ISO 3888-1 double lane change, then hard braking, at h = 1 ms: |g| < 0.1 mm every step,
  // <= 2 Newton iterations per step (the paper needed one; the lambda-increment criterion
  // usually takes a second one to pin the joint force).
  struct Case {
    const char* file;
    double speed_mps, brake_time_s, front_pa, rear_pa, seconds;
  };
  for (const Case& k : {Case{kCarTrailer, 60 / 3.6, 10.0, 8e6, 4e6, 14.0},
                        Case{kTractorSemi, 50 / 3.6, 13.0, 7e5, 7e5, 18.0}}) {
    Combination c(load(k.file), 1e-3);
    const DriftStats st =
        lane_change_and_brake(c, k.speed_mps, k.brake_time_s, k.front_pa, k.rear_pa, k.seconds);
    print_stats(k.file, st);
    ASSERT_TRUE(st.finite);
    EXPECT_LT(st.max_violation_m, 1e-4);
    EXPECT_LE(st.max_iterations, 2);
    // and it really braked to (near) stand-still and turned through the lane change
    EXPECT_LT(std::abs(c.unit(0).speeds()(0)), 2.0);
    // the paper's criterion, |g| only (with the same 1e-7 m tolerance): for comparison
    CombinationParams p = load(k.file);
    p.newton.criterion = solver::NewtonCriterion::kPosition;
    Combination position_only(p, 1e-3);
    const DriftStats sp = lane_change_and_brake(position_only, k.speed_mps, k.brake_time_s,
                                                k.front_pa, k.rear_pa, k.seconds);
    print_stats("  |g|-only criterion", sp);
    EXPECT_LT(sp.max_violation_m, 1e-4);
    EXPECT_LE(sp.max_iterations, 2);
  }
}

/// Joint-0 force and the leading unit's speed, sampled every `every` steps.
struct Sample {
  Vec3 force_n;
  double speed_mps;
};

template <typename Model>
std::vector<Sample> force_history(Model& m, double speed_mps, double seconds, long every,
                                  double brake_time_s, double front_pa, double rear_pa) {
  m.reset(0, 0, 0);
  m.set_forward_speed(speed_mps);
  driver::PathDriver d(
      lane_change_then_brake(m.unit(0).params(), speed_mps, brake_time_s, front_pa, rear_pa));
  Signals s = driver_inputs();
  std::vector<Sample> out;
  const long n = std::lround(seconds / m.step_size_s());
  for (long k = 0; k < n; ++k) {
    d.update(m.time_s(), s);
    if (m.step(s) != StepStatus::kOk) return out;
    if ((k + 1) % every == 0) out.push_back({m.joint_force_n(0), m.unit(0).speeds()(0)});
  }
  return out;
}

/// max_t |a - ref| / max_t |ref| per component, over the samples where the reference moves
/// faster than min_speed_mps.
Vec3 relative_error(const std::vector<Sample>& a, const std::vector<Sample>& ref,
                    double min_speed_mps) {
  Vec3 err = Vec3::Zero(), peak = Vec3::Zero();
  for (std::size_t i = 0; i < std::min(a.size(), ref.size()); ++i) {
    peak = peak.cwiseMax(ref[i].force_n.cwiseAbs());
    if (std::abs(ref[i].speed_mps) < min_speed_mps) continue;
    err = err.cwiseMax((a[i].force_n - ref[i].force_n).cwiseAbs());
  }
  return err.cwiseQuotient(peak);
}

TEST(Combination, JointForcesMatchStiffSpringBaselineWithinFivePercentOfPeak) {
  // Baseline: the joints as stiff spring-dampers (config: relative modes ~1000 rad/s, damping
  // ratio ~0.5; softer springs, e.g. the paper's pendulum rod c = 5e7 N/m, add a drawbar mode at
  // 10-50 Hz that rings when the brakes come on), one implicit matrix for the whole combination
  // (eqs. 32-38). Double lane change, then braking to stand-still.
  //  (a) DAE at h = 1 ms vs the spring baseline at the same h (same vehicle discretization: the
  //      coupling alone), whole run: within 5 % of the peak of each force component.
  //  (b) DAE at h = 1 ms vs the spring baseline at h = 0.1 ms (reference), while moving
  //      (> 0.5 m/s): within 5 %. After stand-still the vehicle model itself depends on h (brake
  //      stick prediction, tire deflection at rest), with and without coupling: printed only.
  struct Case {
    const char* file;
    double speed_mps, seconds, brake_time_s, front_pa, rear_pa;
  };
  for (const Case& k : {Case{kCarTrailer, 60 / 3.6, 12.0, 9.0, 8e6, 4e6},
                        Case{kTractorSemi, 50 / 3.6, 15.0, 12.0, 7e5, 7e5}}) {
    const CombinationParams p = load(k.file);
    Combination dae(p, 1e-3);
    ForceCoupledCombination spring_ref(p, 1e-4), spring(p, 1e-3);
    const auto f_dae =
        force_history(dae, k.speed_mps, k.seconds, 1, k.brake_time_s, k.front_pa, k.rear_pa);
    const auto f_ref = force_history(spring_ref, k.speed_mps, k.seconds, 10, k.brake_time_s,
                                     k.front_pa, k.rear_pa);
    const auto f_spring =
        force_history(spring, k.speed_mps, k.seconds, 1, k.brake_time_s, k.front_pa, k.rear_pa);
    const auto expected = static_cast<std::size_t>(std::lround(k.seconds * 1e3));
    ASSERT_EQ(f_dae.size(), expected);
    ASSERT_EQ(f_ref.size(), expected);
    ASSERT_EQ(f_spring.size(), expected);
    Vec3 peak = Vec3::Zero();
    for (const Sample& s : f_ref) peak = peak.cwiseMax(s.force_n.cwiseAbs());
    const Vec3 same_h = relative_error(f_dae, f_spring, 0.0);
    const Vec3 moving = relative_error(f_dae, f_ref, 0.5);
    const Vec3 all = relative_error(f_dae, f_ref, 0.0);
    const Vec3 spring_all = relative_error(f_spring, f_ref, 0.0);
    std::printf(
        "%s: peak |F| (%.0f, %.0f, %.0f) N; max error / peak (x, y, z):\n"
        "  DAE 1 ms vs spring 1 ms, whole run      (%.2f, %.2f, %.2f) %%\n"
        "  DAE 1 ms vs spring 0.1 ms, moving       (%.2f, %.2f, %.2f) %%\n"
        "  DAE 1 ms vs spring 0.1 ms, whole run    (%.2f, %.2f, %.2f) %%\n"
        "  spring 1 ms vs spring 0.1 ms, whole run (%.2f, %.2f, %.2f) %%\n",
        k.file, peak.x(), peak.y(), peak.z(), 100 * same_h.x(), 100 * same_h.y(), 100 * same_h.z(),
        100 * moving.x(), 100 * moving.y(), 100 * moving.z(), 100 * all.x(), 100 * all.y(),
        100 * all.z(), 100 * spring_all.x(), 100 * spring_all.y(), 100 * spring_all.z());
    EXPECT_LT(same_h.maxCoeff(), 0.05);
    EXPECT_LT(moving.maxCoeff(), 0.05);
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

TEST(Combination, ThreeUnitTruckDollySemitrailerChain) {
  // Any chain: the 6x4 rigid truck pulls a 2-axle dolly by a drawbar (ball joint at the eye),
  // the dolly carries the semitrailer on a fifth wheel - 3 units, 7 multipliers. Lane change at
  // 50 km/h, then braking: drift, Newton iterations, static loads handed down the chain.
  const CombinationParams semi = load(kTractorSemi);
  CombinationParams p;
  p.newton = default_combination_newton_params();
  p.units.push_back(
      io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/truck-3axle.toml"));
  vehicle::VehicleParams dolly = semi.units[1];
  dolly.name = "dolly";
  dolly.chassis.mass_kg = 900;
  dolly.chassis.inertia_kgm2 = {600, 900, 1200};
  dolly.chassis.cg_height_m = 0.9;
  dolly.chassis.drag_area_m2 = 0.5;
  dolly.axles.resize(2);
  dolly.axles[0].position_x_m = 0.65;
  dolly.axles[1].position_x_m = -0.65;
  p.units.push_back(dolly);
  p.units.push_back(semi.units[1]);
  p.joints.push_back(
      make_joint_params(JointKind::kBall, p.units[0], -4.2, p.units[1], 3.2, 0.9));  // drawbar
  p.joints.push_back(
      make_joint_params(JointKind::kFifthWheel, p.units[1], 0.0, p.units[2], 4.8, 1.2));
  Combination c(p, 1e-3);
  // static loads: the semitrailer's kingpin load on the dolly, the dolly's drawbar load on the
  // truck, after 1 s standing
  Signals s = driver_inputs();
  s[Signal::kGearRequest] = 0;
  for (int k = 0; k < 1000; ++k) ASSERT_EQ(c.step(s), StepStatus::kOk);
  std::printf(
      "truck + dolly + semitrailer standing: drawbar force (%.0f, %.0f, %.0f) N, kingpin "
      "force (%.0f, %.0f, %.0f) N (static %.0f / %.0f N)\n",
      c.joint_force_n(0).x(), c.joint_force_n(0).y(), c.joint_force_n(0).z(),
      c.joint_force_n(1).x(), c.joint_force_n(1).y(), c.joint_force_n(1).z(),
      c.unit(1).framework().support_load_n(), c.unit(2).framework().support_load_n());
  EXPECT_NEAR(-c.joint_force_n(1).z(), c.unit(2).framework().support_load_n(),
              0.02 * c.unit(2).framework().support_load_n());
  EXPECT_NEAR(-c.joint_force_n(0).z(), c.unit(1).framework().support_load_n(),
              0.02 * std::abs(c.unit(1).framework().support_load_n()) + 50);
  const DriftStats st = lane_change_and_brake(c, 50 / 3.6, 13.0, 7e5, 7e5, 18.0);
  print_stats("truck + dolly + semitrailer", st);
  ASSERT_TRUE(st.finite);
  EXPECT_LT(st.max_violation_m, 1e-4);
  EXPECT_LE(st.max_iterations, 2);
  EXPECT_LT(std::abs(c.unit(0).speeds()(0)), 2.0);
  ModelReport report;
  c.fill_report(report);
  EXPECT_EQ(report.unit_count, 3);
  EXPECT_EQ(report.joint_count, 2);
  EXPECT_EQ(report.units[2].wheel_count, 6);
}

TEST(Combination, NoNaNAtOneAndTwoMilliseconds) {
  for (const double h : {1e-3, 2e-3}) {
    for (const char* file : {kCarTrailer, kTractorSemi}) {
      Combination c(load(file), h);
      const bool truck = file == std::string(kTractorSemi);
      const DriftStats st =
          lane_change_and_brake(c, truck ? 50 / 3.6 : 60 / 3.6, truck ? 13.0 : 10.0,
                                truck ? 7e5 : 8e6, truck ? 7e5 : 4e6, truck ? 18.0 : 14.0);
      std::printf("h = %.0f ms ", h * 1e3);
      print_stats(file, st);
      EXPECT_TRUE(st.finite);
      EXPECT_LT(st.max_violation_m, 1e-4);
    }
  }
}

TEST(Combination, ParallelIsBitwiseSerialAndNoStepAllocates) {
  CombinationParams p = load(kCarTrailer);
  Combination serial(p, 1e-3);
  p.parallel = true;
  p.begin_step_runner = make_thread_begin_step_runner;
  Combination parallel(p, 1e-3);
  p.parallel = false;
  ForceCoupledCombination spring(p, 1e-3);
  serial.set_forward_speed(20);
  parallel.set_forward_speed(20);
  spring.set_forward_speed(20);
  Signals a = driver_inputs(), b = driver_inputs(), c = driver_inputs();
  const auto inputs = [](double t, Signals& s) {
    s[Signal::kThrottlePedal] = t < 2 ? 0.3 : 0;
    s[Signal::kSteeringWheelAngleCmd] = 1.5 * std::sin(2 * t);
    s[Signal::kBrakePressureFront] = t > 2 ? 5e6 : 0;
    s[Signal::kBrakePressureRear] = t > 2 ? 2.5e6 : 0;
  };
  for (int k = 0; k < 200; ++k) {  // lazy one-time initializations outside the counter
    inputs(serial.time_s(), a);
    inputs(parallel.time_s(), b);
    inputs(spring.time_s(), c);
    ASSERT_EQ(serial.step(a), StepStatus::kOk);
    ASSERT_EQ(parallel.step(b), StepStatus::kOk);
    ASSERT_EQ(spring.step(c), StepStatus::kOk);
  }
  ModelReport report;
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  for (int k = 0; k < 3800; ++k) {
    inputs(serial.time_s(), a);
    inputs(parallel.time_s(), b);
    inputs(spring.time_s(), c);
    ASSERT_EQ(serial.step(a), StepStatus::kOk);
    ASSERT_EQ(parallel.step(b), StepStatus::kOk);
    ASSERT_EQ(spring.step(c), StepStatus::kOk);
    serial.fill_report(report);
  }
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  // many more hand-overs to the worker thread (a lost wake-up would hang here: ctest timeout)
  for (int k = 0; k < 30000; ++k) {
    inputs(serial.time_s(), a);
    inputs(parallel.time_s(), b);
    ASSERT_EQ(serial.step(a), StepStatus::kOk);
    ASSERT_EQ(parallel.step(b), StepStatus::kOk);
  }
  EXPECT_EQ(a.value, b.value);  // bitwise: the same arithmetic on another thread
  EXPECT_EQ(serial.unit(1).coordinates(), parallel.unit(1).coordinates());
  EXPECT_EQ(report.unit_count, 2);
  EXPECT_EQ(report.joint_count, 1);
  EXPECT_EQ(report.units[1].wheel_count, 2);
  EXPECT_GT(std::abs(report.joints[0].force_n[2]), 100.0);
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
