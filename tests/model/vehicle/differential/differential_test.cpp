// Differentials (issue 17 item 6; model/vehicle/differential/README.md): the torque splits of
// open, locked, limited-slip and viscous differentials against hand calculations on the sedan
// (config/vehicles/sedan.toml, sedan-4x4.toml) and the 6x4 tractor (tractor-6x4-diff.toml), the
// wheel speeds of a steady circle against the track geometry, the locked axle's yaw moment
// against the slip difference it forces, h = 1 ms and no allocation per step.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/tire/tmeasy_characteristic.h"
#include "model/tire/tmeasy_tire.h"
#include "model/vehicle/differential/differential_tree.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::vehicle {
namespace {

using differential::DifferentialKind;
using differential::DifferentialParams;

constexpr int kRearLeft = 2, kRearRight = 3;  // the sedan's rear axle (axle index 1)

VehicleParams load(const char* name) {
  return io::config::load_vehicle_file(std::string(RIG_SOURCE_DIR "/config/vehicles/") + name);
}

/// The sedan (rear-wheel drive) with one differential across its rear axle.
VehicleParams sedan_with(DifferentialKind kind, double preload_nm = 0, double bias_ratio = 1) {
  VehicleParams p = load("sedan.toml");
  DifferentialParams d;
  d.axle = 1;
  d.kind = kind;
  d.preload_nm = preload_nm;
  d.bias_ratio = bias_ratio;
  p.drivetrain.differentials.push_back(d);
  return p;
}

using Inputs = std::function<void(const VehicleModel&, Signals&)>;
using Check = std::function<void(const ModelReport& now, const ModelReport& before, double t)>;

/// Steps `seconds` at h = 1 ms; `check` sees every step's report and the one before.
void drive(VehicleModel& m, double seconds, const Inputs& inputs, const Check& check) {
  Signals s = test::all_driver_inputs();
  ModelReport before, now;
  m.fill_report(before);
  const long n = std::lround(seconds / 1e-3);
  for (long k = 0; k < n; ++k) {
    inputs(m, s);
    ASSERT_EQ(m.step(s), StepStatus::kOk) << "t = " << m.time_s();
    m.fill_report(now);
    check(now, before, m.time_s());
    before = now;
  }
}

const Inputs kFullThrottle = [](const VehicleModel&, Signals& s) {
  s[Signal::kThrottlePedal] = 1.0;
};

const WheelReport& wheel(const ModelReport& r, int i) {
  return r.units[0].wheels[static_cast<std::size_t>(i)];
}

/// The wheel's own balance over the last step: the shaft torque that its tire force, its spin-up
/// and its rolling resistance (the brake's dry friction, brake_torque_nm < 0) take,
/// r_D F_x + J dw/dt - T_B.
double traction_torque_nm(const VehicleParams& p, const ModelReport& now, const ModelReport& before,
                          int i) {
  const double j = p.axles[static_cast<std::size_t>(i / 2)].tire.spin_inertia_kgm2;
  const double r = wheel(now, i).rolling_radius_m;
  return r * wheel(now, i).force_x_n +
         j * (wheel(now, i).spin_radps - wheel(before, i).spin_radps) / 1e-3 -
         wheel(now, i).brake_torque_nm;
}

// ---- split mu (right wheels on ice, mu 0.1), full throttle from rest ----

TEST(Differential, OpenOnIceBothWheelsGetTheLowWheelsTorque) {
  VehicleParams p = sedan_with(DifferentialKind::kOpen);
  p.road.friction_right = 0.1;
  VehicleParams base = load("sedan.toml");  // no [drivetrain.differential]: HalfShafts
  base.road.friction_right = 0.1;
  VehicleModel m(p, 1e-3), b(base, 1e-3);
  Signals sb = test::all_driver_inputs();
  sb[Signal::kThrottlePedal] = 1.0;
  int spinning = 0;
  drive(m, 3.0, kFullThrottle, [&](const ModelReport& now, const ModelReport& before, double t) {
    ASSERT_EQ(b.step(sb), StepStatus::kOk);
    ModelReport rb;
    b.fill_report(rb);
    const double tl = wheel(now, kRearLeft).drive_torque_nm;
    const double tr = wheel(now, kRearRight).drive_torque_nm;
    EXPECT_NEAR(tl, tr, 1e-9 * std::abs(tr) + 1e-9);  // the open split, exactly
    // the same as today's open differentials (a different arithmetic, the same equations)
    EXPECT_NEAR(tr, wheel(rb, kRearRight).drive_torque_nm, 1e-6 * std::abs(tr) + 1e-6);
    if (t < 0.5) return;
    // the ice wheel spins: its torque is what its traction and spin-up take, and that is what
    // the dry wheel gets
    ASSERT_GT(wheel(now, kRearRight).spin_radps, 2 * wheel(now, kRearLeft).spin_radps);
    EXPECT_NEAR(tr, traction_torque_nm(p, now, before, kRearRight), 0.03 * tr) << "t = " << t;
    ++spinning;
  });
  EXPECT_GE(spinning, 2500);
  ModelReport r;
  m.fill_report(r);
  EXPECT_EQ(r.differential_count, 1);
  EXPECT_EQ(r.differentials[0].locked, 0);
  // the ice wheel's longitudinal force at its friction limit: between the tire's sliding force
  // F_S and its maximum F_M at mu 0.1 and its load (it slides: s_x >> s_M)
  const WheelReport& ice = wheel(r, kRearRight);
  const tire::TireCharacteristic ch =
      tire::characteristic_at(p.axles[1].tire.tmeasy, ice.tire_load_n, 0.1);
  EXPECT_LT(ice.force_x_n, 1.01 * ch.x.max_force_n);
  EXPECT_GT(ice.force_x_n, 0.99 * ch.x.slide_force_n);
  EXPECT_GT(ice.slip_x, ch.x.max_slip);
}

TEST(Differential, LockedHighMuWheelCarriesTheRest) {
  VehicleParams p = sedan_with(DifferentialKind::kLocked);
  p.road.friction_right = 0.1;
  VehicleModel m(p, 1e-3);
  double max_high = 0, max_low = 0;
  drive(m, 3.0, kFullThrottle, [&](const ModelReport& now, const ModelReport& before, double t) {
    const double tl = wheel(now, kRearLeft).drive_torque_nm;
    const double tr = wheel(now, kRearRight).drive_torque_nm;
    ASSERT_EQ(now.differentials[0].locked, 1);
    // both sides turn as one
    EXPECT_EQ(now.differentials[0].output_a_speed_radps, now.differentials[0].output_b_speed_radps);
    if (t < 0.5) return;
    // each wheel takes what its own traction (and spin-up) takes: the ice wheel its little,
    // the dry wheel the rest of the input torque, up to its traction
    EXPECT_NEAR(tr, traction_torque_nm(p, now, before, kRearRight), 0.05 * std::abs(tl));
    EXPECT_NEAR(tl, traction_torque_nm(p, now, before, kRearLeft), 0.05 * std::abs(tl));
    // up to its traction: the dry wheel's force within its tire's F_M at mu 1
    const WheelReport& dry = wheel(now, kRearLeft);
    EXPECT_LE(dry.force_x_n,
              tire::characteristic_at(p.axles[1].tire.tmeasy, dry.tire_load_n, 1.0).x.max_force_n);
    max_high = std::max(max_high, tl);
    max_low = std::max(max_low, tr);
  });
  EXPECT_GT(max_high, 3 * max_low);  // the dry wheel carries most of it
}

TEST(Differential, LimitedSlipTorqueDifferenceIsTheLockingTorque) {
  constexpr double kPreload = 40, kBias = 2;  // T_L = 40 N m + |T_in| / 3
  VehicleParams p = sedan_with(DifferentialKind::kLimitedSlip, kPreload, kBias);
  p.road.friction_right = 0.1;
  VehicleModel m(p, 1e-3);
  int slipping = 0;
  drive(m, 3.0, kFullThrottle, [&](const ModelReport& now, const ModelReport& before, double) {
    if (now.differentials[0].locked == 1) return;  // the clutch sticks
    ++slipping;
    const double t_in = wheel(before, kRearLeft).drive_torque_nm +
                        wheel(before, kRearRight).drive_torque_nm;  // the step's start
    const double locking = kPreload + (kBias - 1) / (kBias + 1) * std::abs(t_in);
    const double diff =
        wheel(now, kRearLeft).drive_torque_nm - wheel(now, kRearRight).drive_torque_nm;
    // the slower (dry, left) wheel gets the more
    EXPECT_NEAR(diff, locking, 1e-9 * locking);
    EXPECT_GT(now.differentials[0].output_b_speed_radps, now.differentials[0].output_a_speed_radps);
  });
  EXPECT_GT(slipping, 2000);
}

// ---- all-wheel drive, the 6x4 tandem ----

double axle_torque(const ModelReport& r, int axle) {
  return wheel(r, 2 * axle).drive_torque_nm + wheel(r, 2 * axle + 1).drive_torque_nm;
}

TEST(Differential, CentreOpenSplits40To60Exactly) {
  VehicleParams p = load("sedan-4x4.toml");
  p.drivetrain.differentials[0].kind = DifferentialKind::kOpen;  // no viscous coupling
  VehicleModel m(p, 1e-3);
  drive(m, 3.0, kFullThrottle, [&](const ModelReport& now, const ModelReport&, double) {
    const double front = axle_torque(now, 0), rear = axle_torque(now, 1);
    EXPECT_NEAR(front, 0.4 * (front + rear), 1e-12 * std::abs(front + rear));
    EXPECT_NEAR(wheel(now, 0).drive_torque_nm, wheel(now, 1).drive_torque_nm,
                1e-9 * std::abs(front));  // the open front differential
  });
}

TEST(Differential, InterAxleSplits50To50AndMatchesTodaysTractor) {
  const VehicleParams p = load("tractor-6x4-diff.toml");
  const VehicleParams base = load("tractor-6x4.toml");
  VehicleModel m(p, 1e-3), b(base, 1e-3);
  Signals sb = test::all_driver_inputs();
  sb[Signal::kThrottlePedal] = 1.0;
  drive(m, 3.0, kFullThrottle, [&](const ModelReport& now, const ModelReport&, double) {
    ASSERT_EQ(b.step(sb), StepStatus::kOk);
    ModelReport rb;
    b.fill_report(rb);
    const double a2 = axle_torque(now, 1), a3 = axle_torque(now, 2);
    EXPECT_NEAR(a2, 0.5 * (a2 + a3), 1e-12 * std::abs(a2 + a3));
    for (int i = 2; i < 6; ++i)
      EXPECT_NEAR(wheel(now, i).drive_torque_nm, wheel(rb, i).drive_torque_nm,
                  1e-6 * std::abs(a2) + 1e-6);
  });
  ModelReport r;
  m.fill_report(r);
  ASSERT_EQ(r.differential_count, 3);
  // the inter-axle differential's input is the carrier; its outputs the axle differentials'
  // inputs
  EXPECT_NEAR(r.differentials[1].input_speed_radps, r.differentials[0].output_a_speed_radps, 1e-12);
  EXPECT_NEAR(r.differentials[2].input_speed_radps, r.differentials[0].output_b_speed_radps, 1e-12);
}

TEST(Differential, DriverLocksTheTandem) {
  VehicleParams p = load("tractor-6x4-diff.toml");
  p.road.friction_right = 0.1;
  VehicleModel m(p, 1e-3);
  const Inputs locks = [](const VehicleModel& v, Signals& s) {
    s[Signal::kThrottlePedal] = 1.0;
    s[Signal::kDifferentialLockBetweenCmd] = v.time_s() >= 0.9995 ? 1 : 0;  // from step 1000 on
    s[Signal::kDifferentialLockAxleCmd] = v.time_s() >= 1.9995 ? 1 : 0;
  };
  drive(m, 3.0, locks, [&](const ModelReport& now, const ModelReport&, double t) {
    const auto& d = now.differentials;
    EXPECT_EQ(d[0].locked, t > 1.0005 ? 1 : 0) << t;
    EXPECT_EQ(d[1].locked, t > 2.0005 ? 1 : 0) << t;
    if (t > 2.0005) {  // all locked: every output turns with the carrier
      for (int j = 0; j < 3; ++j) {
        EXPECT_EQ(d[static_cast<std::size_t>(j)].output_a_speed_radps, d[0].input_speed_radps);
        EXPECT_EQ(d[static_cast<std::size_t>(j)].output_b_speed_radps, d[0].input_speed_radps);
      }
    }
  });
}

// ---- the steady circle ----

/// A steady circle: the wheel at `wheel_angle_rad`, speed held at v by the throttle.
Inputs circle(double wheel_angle_rad, double v_mps) {
  return [=](const VehicleModel&, Signals& s) {
    s[Signal::kSteeringWheelAngleCmd] = wheel_angle_rad;
    s[Signal::kThrottlePedal] =
        std::clamp(0.15 + 0.5 * (v_mps - s[Signal::kVehicleSpeed]), 0.0, 1.0);
  };
}

struct Circle {
  ModelReport r;
  double v_mps, yaw_radps;
};

Circle steady_circle(const VehicleParams& p, double wheel_angle_rad, double v_mps) {
  VehicleModel m(p, 1e-3);
  m.set_forward_speed(v_mps);
  Circle c{};
  drive(m, 10.0, circle(wheel_angle_rad, v_mps),
        [](const ModelReport&, const ModelReport&, double) {});
  m.fill_report(c.r);
  c.v_mps = c.r.units[0].velocity_mps[0];
  c.yaw_radps = c.r.units[0].angular_velocity_radps[2];
  return c;
}

TEST(Differential, OpenInACircleWheelSpeedsFollowTheTrack) {
  const VehicleParams p = sedan_with(DifferentialKind::kOpen);
  const Circle c = steady_circle(p, 1.5, 8.0);
  const double t = p.axles[1].track_m;
  const double radius = c.v_mps / c.yaw_radps;  // of the rear axle's centre (no lateral speed
                                                // along the wheels' axis at the rear)
  ASSERT_GT(radius, 10.0);
  ASSERT_LT(radius, 60.0);
  const double inner = wheel(c.r, kRearLeft).spin_radps * wheel(c.r, kRearLeft).rolling_radius_m;
  const double outer = wheel(c.r, kRearRight).spin_radps * wheel(c.r, kRearRight).rolling_radius_m;
  EXPECT_NEAR(inner / outer, (radius - t / 2) / (radius + t / 2), 0.002);
  EXPECT_NEAR(c.r.differentials[0].output_a_speed_radps, wheel(c.r, kRearLeft).spin_radps, 0.01);
}

TEST(Differential, LockedInACircleResistsTheYaw) {
  const VehicleParams open_p = sedan_with(DifferentialKind::kOpen);
  const VehicleParams locked_p = sedan_with(DifferentialKind::kLocked);
  // a wide circle (lateral slips small: TMeasy's characteristics at their initial slopes)
  const Circle open = steady_circle(open_p, 0.8, 8.0);
  const Circle locked = steady_circle(locked_p, 0.8, 8.0);
  const double t = locked_p.axles[1].track_m;
  const auto moment = [&](const Circle& c) {  // about z from the rear axle's F_x
    return t / 2 * (wheel(c.r, kRearRight).force_x_n - wheel(c.r, kRearLeft).force_x_n);
  };
  ASSERT_GT(locked.yaw_radps, 0.1);  // a left turn: the left wheel inside
  EXPECT_LT(moment(locked), 0.0);    // against the yaw
  EXPECT_LT(std::abs(moment(open)), 0.1 * std::abs(moment(locked)));
  // hand calculation: both wheels at one speed w, each at its own path's speed
  // v_i = v -+ r t/2; slips s_i = (r_D w - v_i) / (r_D w) (TMeasy's, Rill 2011 eq. 3.41),
  // F_x,i = F(s_i) of the tire's longitudinal characteristic at F_z,i (the lateral slip left out)
  const auto& tire = locked_p.axles[1].tire.tmeasy;
  double forces[2];
  for (int k = 0; k < 2; ++k) {
    const WheelReport& w = wheel(locked.r, kRearLeft + k);
    const double path = locked.v_mps + (k == 0 ? -1 : 1) * locked.yaw_radps * t / 2;
    const double rw = w.rolling_radius_m * w.spin_radps;
    const double slip = (rw - path) / rw;
    const tire::TireCharacteristic ch = tire::characteristic_at(tire, w.tire_load_n, w.road_mu);
    forces[k] = std::copysign(tire::evaluate_characteristic(ch.x, std::abs(slip)).force_n, slip);
  }
  const double hand = t / 2 * (forces[1] - forces[0]);
  std::printf("locked axle in a circle (R %.1f m): M_z %.1f N m, hand %.1f N m, open %.1f N m\n",
              locked.v_mps / locked.yaw_radps, moment(locked), hand, moment(open));
  EXPECT_NEAR(moment(locked), hand, 0.1 * std::abs(hand));
  // and the slip difference itself from the geometry alone: r_D w the same for both
  const double geometric = (1 / (locked.v_mps - locked.yaw_radps * t / 2) -
                            1 / (locked.v_mps + locked.yaw_radps * t / 2));
  EXPECT_GT(geometric, 0);
}

// ---- viscous centre: the transfer is c dw ----

TEST(Differential, ViscousCentreTransfersCTimesSpeedDifference) {
  VehicleParams p = load("sedan-4x4.toml");
  p.drivetrain.differentials.resize(1);  // the viscous centre, open axles
  const double c = p.drivetrain.differentials[0].viscous_nmspr;
  const Circle circle = steady_circle(p, 2.0, 8.0);
  const ModelReport& r = circle.r;
  const double front = axle_torque(r, 0), rear = axle_torque(r, 1);
  const DifferentialReport& centre = r.differentials[0];
  const double dw = centre.output_a_speed_radps - centre.output_b_speed_radps;
  // the front axle runs on the larger radii: it turns faster and gives torque to the rear
  EXPECT_GT(dw, 0.05);
  EXPECT_NEAR(front - 0.4 * (front + rear), -c * dw, 1e-6 * c * dw);
  // the speed difference: the axles' mean wheel speeds (open axle differentials)
  const double front_mean = 0.5 * (wheel(r, 0).spin_radps + wheel(r, 1).spin_radps);
  const double rear_mean = 0.5 * (wheel(r, 2).spin_radps + wheel(r, 3).spin_radps);
  EXPECT_NEAR(dw, front_mean - rear_mean, 0.02 * dw);
}

// ---- the file: sedan-4x4.toml, and a 6x6 tree with a group side ----

TEST(DifferentialConfig, Sedan4x4AsWritten) {
  const VehicleParams p = load("sedan-4x4.toml");
  const auto& d = p.drivetrain.differentials;
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].axle, -1);
  EXPECT_EQ(d[0].side_a_axles, std::vector<int>{0});
  EXPECT_EQ(d[0].side_b_axles, std::vector<int>{1});
  EXPECT_EQ(d[0].kind, DifferentialKind::kViscous);
  EXPECT_EQ(d[0].split, 0.4);
  EXPECT_EQ(d[0].viscous_nmspr, 50.0);
  EXPECT_TRUE(d[0].lockable);
  EXPECT_EQ(d[1].axle, 1);
  EXPECT_EQ(d[1].kind, DifferentialKind::kLimitedSlip);
  EXPECT_EQ(d[1].preload_nm, 40.0);
  EXPECT_EQ(d[1].bias_ratio, 2.0);
  EXPECT_FALSE(d[1].lockable);
  EXPECT_EQ(differential::differential_count(p), 3);  // + the open front
  EXPECT_EQ(differential::differential_count(load("sedan.toml")), 0);
}

/// The 6x4 tractor with its front axle driven too: a centre differential 30 % to the front
/// against the tandem (a side of two axles), the inter-axle differential between these.
VehicleParams six_by_six() {
  const std::string file = ::testing::TempDir() + "/tractor-6x6.toml";
  std::string text;
  {
    std::ifstream in(RIG_SOURCE_DIR "/config/vehicles/tractor-6x4.toml");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const auto front = text.find("driven = false");
  text.replace(front, 14, "driven = true");
  text +=
      "\n[[drivetrain.differential]]\nbetween = [[1], [2, 3]]\nsplit = 0.3\n"
      "\n[[drivetrain.differential]]\nbetween = [2, 3]\n";
  std::ofstream(file) << text;
  return io::config::load_vehicle_file(file);
}

TEST(DifferentialTree, SixBySixWithAGroupSide) {
  const VehicleParams p = six_by_six();
  const differential::DifferentialTree t = differential::build_tree(p);
  ASSERT_EQ(t.count, 5);  // centre, inter-axle, then the open ones across axles 1, 2, 3
  ASSERT_EQ(t.leaf_count, 6);
  // hand: the front wheels under the centre's side a (1 - 0.3), the tandem's under side b (-0.3);
  // the inter-axle: axle 2 side a (0.5), axle 3 side b (-0.5); each axle's: left 0.5, right -0.5
  const double g[6][5] = {{0.7, 0, 0.5, 0, 0},     {0.7, 0, -0.5, 0, 0},
                          {-0.3, 0.5, 0, 0.5, 0},  {-0.3, 0.5, 0, -0.5, 0},
                          {-0.3, -0.5, 0, 0, 0.5}, {-0.3, -0.5, 0, 0, -0.5}};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j) EXPECT_DOUBLE_EQ(t.g(i, j), g[i][j]) << i << " " << j;
  // inputs: the inter-axle's is the centre's side b, axle 3's the inter-axle's side b
  EXPECT_DOUBLE_EQ(t.input_row(1, 0), -0.3);
  EXPECT_DOUBLE_EQ(t.input_row(4, 0), -0.3);
  EXPECT_DOUBLE_EQ(t.input_row(4, 1), -0.5);
  EXPECT_DOUBLE_EQ(t.input_row(2, 0), 0.7);
  EXPECT_DOUBLE_EQ(t.input_row(0, 1), 0.0);
  // and driving: 30 % to the front, 35 % to each tandem axle, exactly
  VehicleModel m(p, 1e-3);
  drive(m, 1.0, kFullThrottle, [&](const ModelReport& now, const ModelReport&, double) {
    const double all = axle_torque(now, 0) + axle_torque(now, 1) + axle_torque(now, 2);
    EXPECT_NEAR(axle_torque(now, 0), 0.3 * all, 1e-12 * std::abs(all));
    EXPECT_NEAR(axle_torque(now, 1), 0.35 * all, 1e-12 * std::abs(all));
  });
}

// ---- h = 1 ms, no allocation ----

TEST(Differential, FourByFourOnSplitMuIsStableAndAllocationFree) {
  VehicleParams p = load("sedan-4x4.toml");
  p.road.friction_right = 0.1;
  VehicleModel m(p, 1e-3);
  Signals s = test::all_driver_inputs();
  s[Signal::kThrottlePedal] = 1.0;
  for (int k = 0; k < 500; ++k) ASSERT_EQ(m.step(s), StepStatus::kOk);
  test::AllocationCounter counter;
  Eigen::internal::set_is_malloc_allowed(false);
  double max_jump = 0, max_torque = 0;
  ModelReport before, now;
  m.fill_report(before);
  for (int k = 0; k < 5500; ++k) {
    s[Signal::kDifferentialLockBetweenCmd] = (k > 2000 && k < 3500) ? 1 : 0;
    ASSERT_EQ(m.step(s), StepStatus::kOk);
    m.fill_report(now);
    for (int i = 0; i < 4; ++i) {
      max_torque = std::max(max_torque, std::abs(wheel(now, i).drive_torque_nm));
      if (k != 2001 && k != 3500)  // (the lock's own steps)
        max_jump = std::max(
            max_jump, std::abs(wheel(now, i).drive_torque_nm - wheel(before, i).drive_torque_nm));
    }
    before = now;
  }
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_GT(max_torque, 200);
  EXPECT_LT(max_jump, 0.05 * max_torque);  // no chatter of the clutch or the lock at h = 1 ms
}

}  // namespace
}  // namespace rig::model::vehicle
