// Acceptance tests of the paper's validation cases (issue 3): the quarter car of Fig. 6 and the
// coupled pendulums of sec. 3.4 (the CVODE comparison is in tests/rig/paper).
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "model/paper/coupled_pendulums.h"
#include "model/paper/quarter_car.h"
#include "model/paper/quarter_car_model.h"
#include "tests/support/alloc_counter.h"

namespace rig::model::paper {
namespace {

// ---------------------------------------------------------------- quarter car
struct Trace {
  std::vector<double> t, x, v, omega, force;
  std::vector<bool> stick;
};

Trace run_quarter_car(double h, double t_end = kPaperManeuverEnd_s) {
  QuarterCar car;
  Trace tr;
  const long n = std::lround(t_end / h);
  for (long k = 0; k < n; ++k) {
    car.step(h, paper_maneuver_inputs(static_cast<double>(k) * h));
    tr.t.push_back(static_cast<double>(k + 1) * h);
    tr.x.push_back(car.position_m());
    tr.v.push_back(car.speed_mps());
    tr.omega.push_back(car.wheel_speed_radps());
    tr.force.push_back(car.tire_force_n());
    tr.stick.push_back(car.brake_sticking());
  }
  return tr;
}

// The braked stand-still: the first time after the brake comes on at which the car has come to
// rest (v <= 0 first), and the settled time from which |v| < 1 mm/s holds until the release.
struct StandStill {
  std::size_t first_zero = 0, settled = 0, release = 0;
};

StandStill find_stand_still(const Trace& tr) {
  StandStill s;
  std::size_t i = 0;
  while (tr.t[i] < 8.5 || tr.v[i] > 0.0) ++i;
  s.first_zero = i;
  while (tr.t[s.release + 1] <= kPaperBrakeRelease_s) ++s.release;
  s.settled = s.release;
  while (s.settled > s.first_zero && std::abs(tr.v[s.settled - 1]) < 1e-3) --s.settled;
  return s;
}

void expect_held_at_rest(const Trace& tr, const char* label) {
  const StandStill s = find_stand_still(tr);
  const double t_stop = tr.t[s.first_zero], t_settled = tr.t[s.settled];
  std::printf("[%s] stops at t = %.3f s, |v| < 1 mm/s from t = %.3f s to the release\n", label,
              t_stop, t_settled);
  // The stop is followed by the elastic swing of the tire (x_e from the sliding limit to the
  // holding force, ~19 mm); it has to die out quickly and not creep afterwards.
  EXPECT_GT(t_stop, 9.0) << label;
  EXPECT_LT(t_settled - t_stop, 3.0) << label;
  double creep = 0, max_v = 0;
  for (std::size_t i = s.settled; i <= s.release; ++i) {
    creep = std::max(creep, std::abs(tr.x[i] - tr.x[s.settled]));
    max_v = std::max(max_v, std::abs(tr.v[i]));
    EXPECT_TRUE(tr.stick[i]) << label << " brake slips at t = " << tr.t[i];
    EXPECT_EQ(tr.omega[i], 0.0) << label;
  }
  std::printf("[%s] while held: max |v| = %.2e m/s, creep = %.3f mm\n", label, max_v, creep * 1e3);
  EXPECT_LT(max_v, 1e-3) << label;
  EXPECT_LT(creep, 1e-3) << label;
  // The tire holds the downhill force m g sin(alpha) (eq. 24 at stand-still: x_e' = 0).
  const QuarterCarParams p;
  const double downhill = p.mass_kg * p.gravity_mps2 * p.grade / std::sqrt(1 + p.grade * p.grade);
  EXPECT_NEAR(tr.force[s.release], downhill, 0.01 * downhill) << label;
}

TEST(QuarterCar, HeldAtRestOnTheGradeUntilRelease) {
  expect_held_at_rest(run_quarter_car(1e-3), "h = 1 ms");
}

TEST(QuarterCar, RollsDownhillAfterRelease) {
  const Trace tr = run_quarter_car(1e-3);
  const StandStill s = find_stand_still(tr);
  const QuarterCarParams p;
  // Free rolling: (m + Theta / r^2) a = -m g sin(alpha) (tire force ~0 in free rolling).
  const double sin_a = p.grade / std::sqrt(1 + p.grade * p.grade);
  const double a = -p.mass_kg * p.gravity_mps2 * sin_a /
                   (p.mass_kg + p.wheel_inertia_kgm2 / (p.wheel_radius_m * p.wheel_radius_m));
  const double v_end_expected = a * (kPaperManeuverEnd_s - kPaperBrakeRelease_s);
  EXPECT_NEAR(tr.v.back(), v_end_expected, 0.03 * std::abs(v_end_expected));
  EXPECT_LT(tr.x.back(), tr.x[s.release] - 1.5);  // ~ a t^2 / 2 = 1.9 m back down
  EXPECT_LT(tr.omega.back(), 0.0);
}

TEST(QuarterCar, StableAtTenMilliseconds) {
  const Trace coarse = run_quarter_car(1e-2);
  for (std::size_t i = 0; i < coarse.v.size(); ++i) {
    ASSERT_TRUE(std::isfinite(coarse.v[i]) && std::isfinite(coarse.omega[i]));
    ASSERT_LT(std::abs(coarse.v[i]), 50.0);
    ASSERT_LT(std::abs(coarse.omega[i]), 200.0);
  }
  expect_held_at_rest(coarse, "h = 10 ms");
  const Trace fine = run_quarter_car(1e-3);
  EXPECT_NEAR(coarse.v.back(), fine.v.back(), 0.02);
  EXPECT_NEAR(coarse.x.back(), fine.x.back(), 0.5);
}

TEST(QuarterCar, FirstOrderConvergenceAgainstTenMicroseconds) {
  // Error = max |v - v_ref| over t = 0.1, 0.2, ..., 20 s against an h = 1e-5 run.
  auto samples = [](double h) {
    QuarterCar car;
    std::vector<double> v;
    const long n = std::lround(kPaperManeuverEnd_s / h), every = std::lround(0.1 / h);
    for (long k = 0; k < n; ++k) {
      car.step(h, paper_maneuver_inputs(static_cast<double>(k) * h));
      if ((k + 1) % every == 0) v.push_back(car.speed_mps());
    }
    return v;
  };
  const std::vector<double> ref = samples(1e-5);
  std::map<double, double> error;
  for (const double h : {1e-2, 5e-3, 2e-3, 1e-3}) {
    const std::vector<double> v = samples(h);
    ASSERT_EQ(v.size(), ref.size());
    double e = 0;
    for (std::size_t i = 0; i < v.size(); ++i) e = std::max(e, std::abs(v[i] - ref[i]));
    error[h] = e;
    std::printf("h = %g s: max |v - v_ref| = %.4g m/s\n", h, e);
  }
  const double order = std::log(error[1e-2] / error[1e-3]) / std::log(10.0);
  std::printf("observed order from h = 0.01 to 0.001: %.3f\n", order);
  EXPECT_NEAR(order, 1.0, 0.15);
  EXPECT_GT(error[1e-2], error[5e-3]);
  EXPECT_GT(error[5e-3], error[2e-3]);
  EXPECT_GT(error[2e-3], error[1e-3]);
}

TEST(QuarterCarModel, SignalsInOutAndReport) {
  QuarterCarModel model(QuarterCarParams{}, 1e-3);
  Signals sig;
  sig.set(Signal::kThrottlePedal, 0.5);  // 500 N m
  const test::AllocationCounter counter;
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(model.step(sig), StepStatus::kOk);
  ModelReport report;
  model.fill_report(report);
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_NEAR(model.time_s(), 1.0, 1e-9);
  // (m + Theta/r^2) a = T/r - m g sin(alpha) -> v(1 s) ~ a (tire slip build-up aside)
  const QuarterCarParams p;
  const double sin_a = p.grade / std::sqrt(1 + p.grade * p.grade);
  const double a = (500.0 / p.wheel_radius_m - p.mass_kg * p.gravity_mps2 * sin_a) /
                   (p.mass_kg + p.wheel_inertia_kgm2 / (p.wheel_radius_m * p.wheel_radius_m));
  EXPECT_NEAR(sig[Signal::kVehicleSpeed], a * 1.0, 0.02 * a);
  EXPECT_NEAR(sig[Signal::kLongitudinalAccel], a, 0.02 * a);
  EXPECT_GT(sig[Signal::kWheelSpeedFL], sig[Signal::kVehicleSpeed] / p.wheel_radius_m);
  EXPECT_NEAR(sig[Signal::kPositionX], 0.5 * a, 0.03 * a);
  EXPECT_TRUE(sig.valid[index(Signal::kVehicleSpeed)]);
  EXPECT_EQ(report.unit_count, 1);
  EXPECT_EQ(report.units[0].wheel_count, 1);
  EXPECT_DOUBLE_EQ(report.units[0].wheels[0].drive_torque_nm, 500.0);
  EXPECT_DOUBLE_EQ(report.units[0].velocity_mps[0], sig[Signal::kVehicleSpeed]);
  // full brake pressure 1e7 Pa -> 1500 N m limit holds the car after it stops
  sig.set(Signal::kThrottlePedal, 0.0);
  sig.set(Signal::kBrakePressureFront, 1e7);
  for (int i = 0; i < 4000; ++i) ASSERT_EQ(model.step(sig), StepStatus::kOk);
  EXPECT_LT(std::abs(sig[Signal::kVehicleSpeed]), 1e-3);
  EXPECT_EQ(sig[Signal::kWheelSpeedFL], 0.0);
}

TEST(QuarterCarModel, NonFiniteStepKeepsTheLastFiniteState) {
  QuarterCarModel model(QuarterCarParams{}, 1e-3);
  QuarterCar::State s = model.quarter_car().state();
  s.speed_mps = 1e308;  // finite, but the step overflows
  s.spin_radps = -1e308;
  model.quarter_car().set_state(s);
  Signals sig;
  EXPECT_EQ(model.step(sig), StepStatus::kNonFinite);
  EXPECT_EQ(model.quarter_car().state().speed_mps, 1e308);
  EXPECT_EQ(model.quarter_car().state().spin_radps, -1e308);
  EXPECT_EQ(model.time_s(), 0.0);
}

// ---------------------------------------------------------------- pendulums
TEST(CoupledPendulums, InitialGeometryIsThePapers) {
  const CoupledPendulumsParams p;
  EXPECT_NEAR(rod_length_m(p), std::sqrt(2.5), 1e-15);
  // dg/dphi2 with the corrected term -a2 sin(phi2) vs finite differences at a generic point
  const double phi1 = 0.7, phi2 = -0.4, d = 1e-7;
  const RodGeometry r = rod_geometry(p, phi1, phi2);
  const double fd2 =
      (rod_geometry(p, phi1, phi2 + d).length_m - rod_geometry(p, phi1, phi2 - d).length_m) /
      (2 * d);
  const double fd1 =
      (rod_geometry(p, phi1 + d, phi2).length_m - rod_geometry(p, phi1 - d, phi2).length_m) /
      (2 * d);
  EXPECT_NEAR(r.dl_dphi2_m, fd2, 1e-8);
  EXPECT_NEAR(r.dl_dphi1_m, fd1, 1e-8);
}

TEST(CoupledPendulums, AtOneMillisecondTwoNewtonIterationsKeepTheRod) {
  CoupledPendulums p;
  std::map<int, int> histogram;
  double max_g = 0;
  for (int i = 0; i < 5000; ++i) {
    const solver::NewtonReport r = p.step(1e-3);
    ++histogram[r.iterations];
    ASSERT_TRUE(r.converged);
    ASSERT_LE(r.iterations, 2) << "t = " << p.time_s();
    max_g = std::max(max_g, std::abs(p.constraint_violation_m()));
    ASSERT_LT(std::abs(p.constraint_violation_m()), 1e-4) << "t = " << p.time_s();
  }
  std::printf("h = 1 ms, 5000 steps: max |l - s| = %.2e m; iterations:", max_g);
  for (const auto& [k, n] : histogram) std::printf(" %d x %d", n, k);
  std::printf("\n");
}

TEST(CoupledPendulums, StableUpToNinetyMilliseconds) {
  // Stable: every step converges, the rod is kept, and the energy error stays bounded (the
  // paper's scheme is the symplectic Euler: its energy oscillates by O(h) but does not drift)
  // over 20 s - four times the paper's 5 s run.
  std::printf(
      "| h [s] | steps in 5 s | Newton iterations in 5 s (count x iterations) | max |"
      " max |l-s| [m] | max |E-E0| [J], 0-10 s | 10-20 s |\n");
  for (const double h : {0.001, 0.01, 0.02, 0.03, 0.05, 0.07, 0.09}) {
    CoupledPendulums p;
    const double e0 = p.mechanical_energy_j();
    const long n = std::lround(20.0 / h), n5 = std::lround(5.0 / h);
    std::map<int, int> histogram;
    double max_g = 0, de_first = 0, de_second = 0;
    int max_it = 0;
    for (long i = 0; i < n; ++i) {
      const solver::NewtonReport r = p.step(h);
      ASSERT_TRUE(r.converged) << "h = " << h << " t = " << p.time_s();
      ASSERT_TRUE(std::isfinite(p.phi1_rad()) && std::isfinite(p.phi2_rad()));
      if (i < n5) {
        ++histogram[r.iterations];
        max_it = std::max(max_it, r.iterations);
      }
      max_g = std::max(max_g, std::abs(p.constraint_violation_m()));
      const double de = std::abs(p.mechanical_energy_j() - e0);
      (p.time_s() <= 10.0 ? de_first : de_second) =
          std::max(p.time_s() <= 10.0 ? de_first : de_second, de);
    }
    EXPECT_LT(max_g, 1e-4) << "h = " << h;
    EXPECT_LT(de_first, 0.3 * std::abs(e0)) << "h = " << h;
    EXPECT_LT(de_second, 1.5 * de_first + 1e-3 * std::abs(e0)) << "h = " << h;
    std::printf("| %.3f | %ld |", h, n5);
    for (const auto& [k, c] : histogram) std::printf(" %d x %d", c, k);
    std::printf(" | %d | %.1e | %.2f | %.2f |\n", max_it, max_g, de_first, de_second);
  }
}

}  // namespace
}  // namespace rig::model::paper
