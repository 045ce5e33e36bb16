// Closed-loop runs of the vehicle combinations (issue 7) with the rig's path driver (rig/driver)
// and the rig's parallel worker (rig/thread_begin_step_runner.h): drift and Newton iterations
// through an ISO 3888-1 lane change and hard braking, joint forces against the stiff
// spring-damper baseline, the three-unit chain, no NaN at 1 and 2 ms, parallel == serial.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/combination/combination.h"
#include "model/combination/force_coupled.h"
#include "rig/driver/path_driver.h"
#include "rig/thread_begin_step_runner.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/combination_files.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::combination {
namespace {

using test::kCarTrailer;
using test::kTractorSemi;

CombinationParams load(const char* file) { return test::load_combination(file); }

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
  // the gear held: the automatic's shift instant moves by a few ms with h (the threshold
  // crossing) and its shift transient then rings in another phase - the vehicle's step-size
  // dependence, not the coupling's error this compares
  const int gear = m.unit(0).state().gear;
  std::vector<Sample> out;
  const long n = std::lround(seconds / m.step_size_s());
  for (long k = 0; k < n; ++k) {
    d.update(m.time_s(), s);
    s[Signal::kGearRequest] = gear;
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

}  // namespace
}  // namespace rig::model::combination
