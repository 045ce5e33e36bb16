// Acceptance tests of vehicle combinations as index-3 DAEs (issue 7) on
// config/combinations/car-trailer.toml and tractor-semitrailer.toml.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/strict_table.h"
#include "model/combination/combination.h"
#include "model/combination/force_coupled.h"
#include "rig/driver/path_driver.h"
#include "rig/vehicle_config/vehicle_config.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::combination {
namespace {

constexpr const char* kCarTrailer = RIG_SOURCE_DIR "/config/combinations/car-trailer.toml";
constexpr const char* kTractorSemi = RIG_SOURCE_DIR "/config/combinations/tractor-semitrailer.toml";

CombinationParams load(const char* file) {
  const toml::table doc = io::load_toml_file(file);
  io::StrictTable top(doc, file, "top level");
  io::StrictTable m = top.table("model");
  (void)m.string("kind");
  const vehicle_config::CombinationModelSettings s = vehicle_config::read_combination_model(m);
  CombinationParams p;
  p.name = s.name;
  p.units = s.units;
  p.joints = s.joints;
  p.parallel = s.parallel;
  p.newton = default_combination_newton_params();
  return p;
}

Signals driver_inputs() {
  Signals s;
  for (std::size_t i = 0; i < index(kFirstOutput); ++i) {
    s.valid[i] = true;
    s.source[i] = SignalSource::kDriver;
  }
  s[Signal::kGearRequest] = 99;
  return s;
}

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

/// Double lane change at `speed`, then hard braking (ramped to `brake_pa` on both circuits from
/// `brake_time`), on the combination; records |g| and Newton iterations every step.
DriftStats lane_change_and_brake(Combination& c, double speed_mps, double brake_time_s,
                                 double brake_front_pa, double brake_rear_pa, double seconds) {
  c.reset(0, 0, 0);
  c.set_forward_speed(speed_mps);
  driver::PathDriverParams dp = path_driver_for(c.unit(0).params(), 30.0, speed_mps);
  dp.stop_time_s = brake_time_s;
  dp.stop_brake_pressure_front_pa = brake_front_pa;
  dp.stop_brake_pressure_rear_pa = brake_rear_pa;
  dp.stop_brake_ramp_s = 0.2;
  driver::PathDriver d(dp);
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
  }
}

}  // namespace
}  // namespace rig::model::combination
