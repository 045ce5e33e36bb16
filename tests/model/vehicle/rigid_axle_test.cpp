// Rigid axles (issue 17 item 1, model/vehicle/rigid_axle.h) against hand calculations: static
// axle loads (lever rule / a rigid frame on springs), the roll gradient from the roll centres and
// the axles' roll stiffness 2 k (spring_track/2)^2 + bar, camber = axle roll, the wheel-hop and
// tramp frequencies from the springs and tires, h = 1 ms, no allocation, analytic partials.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/driver_inputs.h"
#include "tests/support/fd_jacobians.h"
#include "tests/support/vehicle_rest.h"

namespace rig::model::vehicle {
namespace {

constexpr double kG = 9.81;

VehicleParams rigid_truck() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/truck-3axle-rigid.toml");
}

using test::rest;  // at rest, brakes on, settled (tests/support/vehicle_rest.h)

double axle_load_n(const VehicleModel& m, int a) {
  return m.wheel_load_n(2 * a) + m.wheel_load_n(2 * a + 1);
}

/// Static axle loads of a rigid frame on equal springs at x_a (CG at x = 0): heave z and pitch
/// theta from sum k (z - x_a theta) = W, sum k x_a (z - x_a theta) = 0, so
/// F_a = W (S2 - x_a S1) / (n S2 - S1^2), S1 = sum x_a, S2 = sum x_a^2 - for two axles the
/// lever rule F_1 = W (-x_2) / (x_1 - x_2). Plus the axle's own weight.
std::vector<double> hand_axle_loads(const VehicleParams& p) {
  double s1 = 0, s2 = 0;
  const auto n = static_cast<double>(p.axles.size());
  for (const AxleParams& a : p.axles) s1 += a.position_x_m, s2 += a.position_x_m * a.position_x_m;
  std::vector<double> loads;
  for (const AxleParams& a : p.axles) {
    const double sprung = p.chassis.mass_kg * kG * (s2 - a.position_x_m * s1) / (n * s2 - s1 * s1);
    loads.push_back(sprung + a.rigid.mass_kg * kG);
  }
  return loads;
}

TEST(RigidAxle, ConfigLoadsAsRigidAxlesWithTheirRollCentres) {
  const VehicleParams p = rigid_truck();
  ASSERT_EQ(p.axles.size(), 3u);
  for (const AxleParams& a : p.axles) EXPECT_EQ(a.kind, AxleKind::kRigid);
  // leaf: the eyes' mean height; four-link: the V-rod apex on the axle (upper links meet at x=0)
  EXPECT_DOUBLE_EQ(p.axles[0].rigid.roll_centre_height_m, 0.5 * (0.78 + 0.74));
  EXPECT_DOUBLE_EQ(p.axles[1].rigid.roll_centre_height_m, 0.95);
  EXPECT_DOUBLE_EQ(p.axles[0].unsprung_mass_kg, 350.0);  // half the axle at each wheel
  // four-link, hand: the roll axis through (x_u, h_u) and (x_l, h_l), at the axle x = 0
  EXPECT_DOUBLE_EQ(four_link_roll_centre_m(2.0, 1.0, 6.0, 0.4), 1.0 + (0.4 - 1.0) * (-2.0) / 4.0);
}

TEST(RigidAxle, StaticAxleLoadsMatchTheLeverRule) {
  VehicleParams three = rigid_truck();
  VehicleParams two = three;
  two.axles.pop_back();  // front axle + one drive axle: the lever rule
  for (const VehicleParams* p : {&two, &three}) {
    VehicleModel m(*p, 1e-3);
    Signals s = test::all_driver_inputs();
    rest(m, s, 1.0);
    const std::vector<double> hand = hand_axle_loads(*p);
    for (std::size_t a = 0; a < hand.size(); ++a) {
      const double load = axle_load_n(m, static_cast<int>(a));
      std::printf("%zu axles: axle %zu load %.1f N, hand %.1f N (%.4f %%)\n", p->axles.size(),
                  a + 1, load, hand[a], 100 * (load / hand[a] - 1));
      EXPECT_NEAR(load, hand[a], 1e-3 * hand[a]) << "axle " << a + 1;
    }
  }
}

/// Roll of the body against its axles on a banked road (the tires' lateral forces at the contact
/// patches hold the vehicle): the sprung mass's lateral weight m_s g sin(beta) acts h' above the
/// roll axis (all three roll centres at one height here), against the axles' roll stiffness
/// K = sum 2 k (spring_track/2)^2 + bar less the rolled weight's moment m_s g h'.
double measured_and_hand_roll(double roll_centre_m, double& hand) {
  VehicleParams p = rigid_truck();
  double stiffness = 0;
  for (AxleParams& a : p.axles) {
    a.rigid.roll_centre_height_m = roll_centre_m;
    const double half = 0.5 * a.rigid.spring_track_m;
    stiffness += 2 * a.spring_stiffness_npm * half * half + a.rigid.anti_roll_stiffness_nmprad;
  }
  p.road.bank = 0.05;
  const double lateral = kG * std::sin(std::atan(p.road.bank));
  const double arm = p.chassis.cg_height_m - roll_centre_m;
  const double ms = p.chassis.mass_kg;
  hand = ms * lateral * arm / (stiffness - ms * kG * arm);
  VehicleModel m(p, 1e-3);
  Signals s = test::all_driver_inputs();
  rest(m, s, 2.0);
  const auto& y = m.framework().coordinates();
  double rel = 0;  // body roll against the axles: minus the axles' roll against the body
  for (int a = 0; a < 3; ++a) rel -= y(7 + 2 * a) / 3.0;
  return rel;
}

TEST(RigidAxle, RollGradientFollowsTheRollCentreHeight) {
  for (double rc : {0.5, 0.95}) {
    double hand = 0;
    const double rel = measured_and_hand_roll(rc, hand);
    std::printf(
        "roll centre %.2f m: body roll against the axles %.5f rad, hand %.5f rad "
        "(%.1f %%)\n",
        rc, rel, hand, 100 * (rel / hand - 1));
    EXPECT_GT(rel, 0);  // uphill +y: the body leans downhill, its left side up (roll +)
    EXPECT_NEAR(rel, hand, 0.10 * hand);
  }
}

TEST(RigidAxle, CamberIsTheAxleRollAndRollSteerItsCoefficient) {
  const VehicleParams p = rigid_truck();
  VehicleModel m(p, 1e-3);
  Signals s = test::all_driver_inputs();
  m.set_forward_speed(16.67);
  s[Signal::kSteeringWheelAngleCmd] = 0.8;
  s[Signal::kThrottlePedal] = 0.3;
  for (int k = 0; k < 2000; ++k) ASSERT_EQ(m.step(s), StepStatus::kOk);
  const Eigen::VectorXd y0 = m.framework().coordinates();  // where the next step's pose is taken
  ASSERT_EQ(m.step(s), StepStatus::kOk);
  for (int i = 0; i < 6; ++i) {
    const int a = i / 2;
    const WheelWork& w = m.workspace().wheels[static_cast<std::size_t>(i)];
    const double roll = y0(7 + 2 * a);
    EXPECT_EQ(w.camber_rad, roll) << "wheel " << i;
    EXPECT_GT(std::abs(roll), 1e-4) << "axle " << a + 1 << " rolls in the turn";
    if (a > 0) {  // unsteered: the steer is the roll steer alone
      EXPECT_DOUBLE_EQ(w.steer_rad, p.axles[static_cast<std::size_t>(a)].rigid.roll_steer * roll);
    }
    // the reported hub travel: heave +- (track / 2) roll, at the step's end
    const auto& y1 = m.framework().coordinates();
    const double half = 0.5 * p.axles[static_cast<std::size_t>(a)].track_m;
    EXPECT_DOUBLE_EQ(w.out.hub_travel_m,
                     y1(6 + 2 * a) + (i % 2 == 0 ? half : -half) * y1(7 + 2 * a));
  }
}

/// Period of the free oscillation of framework coordinate j after a kick of its speed: the mean
/// spacing of its upward crossings of the final value over the first cycles.
double measured_frequency_hz(VehicleModel& m, Signals& s, Eigen::Index j, double kick) {
  m.framework().speeds()(j) += kick;
  std::vector<double> values, times;
  for (int k = 0; k < 400; ++k) {
    EXPECT_EQ(m.step(s), StepStatus::kOk);
    values.push_back(m.framework().coordinates()(j));
    times.push_back(m.time_s());
  }
  const double rest_value = values.back();
  std::vector<double> crossings;
  for (std::size_t k = 1; k < values.size(); ++k) {
    const double a = values[k - 1] - rest_value, b = values[k] - rest_value;
    if (a < 0 && b >= 0)
      crossings.push_back(times[k - 1] + (times[k] - times[k - 1]) * a / (a - b));
  }
  if (crossings.size() < 3) return 0;
  const std::size_t n = std::min<std::size_t>(crossings.size(), 5);
  return static_cast<double>(n - 1) / (crossings[n - 1] - crossings[0]);
}

TEST(RigidAxle, WheelHopAndTrampFrequenciesMatchHandValues) {
  VehicleParams p = rigid_truck();
  for (AxleParams& a : p.axles) {  // undamped: the natural frequencies themselves
    a.damper_bump_nspm = a.damper_rebound_nspm = 0;
    a.tire.tmeasy.vertical_damping_nspm = 0;
  }
  // the contact patches free laterally (nearly no friction, a soft lateral tire): the springs'
  // and tires' vertical stiffness alone. With the tire's own lateral stiffness (1.4 MN/m) on
  // 0.001 friction the tramp reads 10.1 Hz at h = 1 ms against 12.3 Hz at 0.1 ms: the lateral
  // deflection states step apart from the framework (eq. 8), and the patches' lateral travel
  // (roll centre height x roll) couples them into the roll.
  p.road.friction = 0.001;
  for (AxleParams& a : p.axles) a.tire.tmeasy.lateral_stiffness_npm *= 0.01;
  for (int a = 0; a < 3; ++a) {
    const AxleParams& ax = p.axles[static_cast<std::size_t>(a)];
    const double k = ax.spring_stiffness_npm, ct = ax.tire.tmeasy.vertical_stiffness_npm;
    const double ts = 0.5 * ax.rigid.spring_track_m, tw = 0.5 * ax.track_m;
    // heave: both springs and tires on the axle's mass
    const double hop = std::sqrt((2 * k + 2 * ct) / ax.rigid.mass_kg) / (2 * M_PI);
    // tramp: about the roll centre (the guidance holds it), inertia by the parallel axes
    const double dz = ax.tire.tmeasy.radius_unloaded_m - ax.rigid.roll_centre_height_m;
    const double inertia = ax.rigid.roll_inertia_kgm2 + ax.rigid.mass_kg * dz * dz;
    const double tramp =
        std::sqrt((2 * k * ts * ts + ax.rigid.anti_roll_stiffness_nmprad + 2 * ct * tw * tw) /
                  inertia) /
        (2 * M_PI);
    for (int mode = 0; mode < 2; ++mode) {
      VehicleModel m(p, 1e-3);
      Signals s = test::all_driver_inputs();
      rest(m, s, 0.5);
      const double f = measured_frequency_hz(m, s, 6 + 2 * a + mode, mode == 0 ? 0.05 : 0.5);
      const double hand = mode == 0 ? hop : tramp;
      std::printf("axle %d %s: %.3f Hz, hand %.3f Hz (%.1f %%)\n", a + 1,
                  mode == 0 ? "wheel hop" : "tramp", f, hand, 100 * (f / hand - 1));
      EXPECT_NEAR(f, hand, 0.05 * hand);
    }
  }
}

TEST(RigidAxle, StepSteerAtOneMillisecondWithoutAllocation) {
  const VehicleParams p = rigid_truck();
  VehicleModel m(p, 1e-3);
  Signals s = test::all_driver_inputs();
  m.set_forward_speed(16.67);
  s[Signal::kThrottlePedal] = 0.3;
  for (int k = 0; k < 500; ++k) ASSERT_EQ(m.step(s), StepStatus::kOk);  // outside the counter
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  double roll_late_min = 1e9, roll_late_max = -1e9;
  for (int k = 0; k < 6000; ++k) {
    s[Signal::kSteeringWheelAngleCmd] = k < 500 ? 0.0 : 0.8;
    ASSERT_EQ(m.step(s), StepStatus::kOk) << "t = " << m.time_s();
    if (k > 5000) {
      const double r = m.framework().coordinates()(9);  // the first drive axle's roll
      roll_late_min = std::min(roll_late_min, r);
      roll_late_max = std::max(roll_late_max, r);
    }
  }
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  const double ay = m.state().acceleration_mps2.y();
  std::printf("step steer: a_y %.2f m/s^2, body roll %.4f rad, axle 2 roll %.5f..%.5f rad\n", ay,
              m.framework().coordinates()(5), roll_late_min, roll_late_max);
  EXPECT_GT(ay, 1.0);
  EXPECT_LT(roll_late_max - roll_late_min, 1e-4);  // steady: no oscillation at h = 1 ms
}

TEST(RigidAxle, AnalyticPartialJacobiansMatchFiniteDifferences) {
  Eigen::internal::set_is_malloc_allowed(true);
  VehicleModel m(rigid_truck(), 1e-3);
  Signals s = test::all_driver_inputs();
  m.set_forward_speed(16.67);
  for (int k = 0; k < 3000; ++k) {
    s[Signal::kSteeringWheelAngleCmd] = k < 500 ? 0.0 : 0.8;
    s[Signal::kThrottlePedal] = 0.3;
    ASSERT_EQ(m.step(s), StepStatus::kOk);
  }
  auto& fw = m.framework();
  const Eigen::Index n = fw.size();
  Eigen::MatrixXd ay(n, n), az(n, n), fy, fz;
  ASSERT_TRUE(fw.force_jacobians(fw.coordinates(), fw.speeds(), ay, az));
  test::fd_jacobians<Eigen::Dynamic>(fw, fw.coordinates(), fw.speeds(), fy, fz);
  // the axles' heave and roll rows and columns (springs, bars, tires vertical) are the whole
  // derivative there; the damping paths are taken at fixed f (eq. 24)
  const auto axles = [&](const Eigen::MatrixXd& x) { return x.bottomRightCorner(n - 6, n - 6); };
  // with the solver's forward-difference step: 5.8e-4 and 3.3e-4
  std::printf("axles' partials vs forward differences: dq/dy %.2e, dq/dz %.2e\n",
              test::relative_error(axles(ay), axles(fy)),
              test::relative_error(axles(az), axles(fz)));
  EXPECT_LT((axles(ay) - axles(fy)).norm(), 1e-3 * axles(fy).norm()) << axles(ay) << "\n"
                                                                     << axles(fy);
  EXPECT_LT((axles(az) - axles(fz)).norm(), 2e-3 * axles(fz).norm()) << axles(az) << "\n"
                                                                     << axles(fz);
  // the body's heave and roll against the axles' (tire vertical through J_P)
  for (Eigen::Index j = 6; j < n; ++j) {
    EXPECT_NEAR(ay(2, j), fy(2, j), 2e-3 * std::abs(fy(j, j))) << "column " << j;
    EXPECT_NEAR(ay(j, 2), fy(j, 2), 2e-3 * std::abs(fy(j, j))) << "row " << j;
  }
  EXPECT_NEAR(ay(2, 2), fy(2, 2), 1e-3 * std::abs(fy(2, 2)));
  EXPECT_NEAR(az(2, 2), fz(2, 2), 2e-2 * std::abs(fz(2, 2)));
}

}  // namespace
}  // namespace rig::model::vehicle
