// The built-in EPS's active return (SteeringParams::active_return, steering/README.md "active
// return"): the torque law against hand values (the pinion angle's slope and saturation, the speed
// trapezoid, the hands-off fade), off with the ECU's assist or the ignition off, its partials
// against finite differences, and a released wheel with no tire load coming to rest inside the
// friction's stick band (hand value from T_max, theta_sat and the rack friction).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/solver/mechanical_stepper.h"
#include "model/vehicle/steering/column_steering.h"
#include "model/vehicle/steering/simple_steering.h"

namespace rig::model::vehicle {
namespace {

SteeringParams sedan_steering() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml").steering;
}

struct Rig {
  explicit Rig(const SteeringParams& params, double speed_mps) : p(params) {
    state.framework_z.setZero(10);
    state.framework_z(0) = speed_mps;
  }
  SteeringParams p;
  VehicleState state;
  VehicleInputs inputs;
  VehicleWorkspace work;
  ColumnSteering system{p, state, inputs};
  SimpleSteering block{system, state, work};
  solver::MechanicalStepper<2> stepper{block};
  /// Wheel and pinion at `pinion_rad`, the torsion bar twisted by `torsion_bar_nm`, at rest.
  void pose(double pinion_rad, double torsion_bar_nm) {
    const double i = p.rack_per_pinion_m_per_rad;
    state.steering_y << pinion_rad + torsion_bar_nm / p.torsion_bar_stiffness_nmpr, pinion_rad * i;
    state.steering_z.setZero();
  }
  /// The EPS's torque at the pinion without the boost curve's share.
  double return_nm(double torsion_bar_nm) {
    return system.assist_torque_nm(state.steering_y, state.steering_z) -
           system.assist_for_torsion_bar_nm(torsion_bar_nm);
  }
};

// The sedan's keys: 2.5 N m from 0.3 rad, trapezoid 1.4 / 2.8 / 11.1 / 22.2 m/s, hands off at 2 N
// m.
TEST(ActiveReturn, TorqueLawSpeedTrapezoidAndHandsOffFade) {
  const SteeringParams p = sedan_steering();
  ASSERT_EQ(p.active_return.torque_max_nm, 2.5);
  ASSERT_EQ(p.active_return.saturation_angle_rad, 0.3);
  struct Case {
    double speed_mps, pinion_rad, torsion_bar_nm, hand_nm;
  };
  const Case cases[] = {
      {5.0, 0.15, 0.0, -1.25},   // linear part: 2.5 x 0.15 / 0.3
      {5.0, 0.6, 0.0, -2.5},     // saturated
      {5.0, -0.6, 0.0, 2.5},     // against the angle
      {0.0, 0.6, 0.0, 0.0},      // parked: none
      {2.1, 0.6, 0.0, -1.25},    // half way up the ramp (2.1 - 1.4) / 1.4
      {16.65, 0.6, 0.0, -1.25},  // half way down (16.65 - 11.1) / 11.1
      {25.0, 0.6, 0.0, 0.0},     // above 80 km/h: none
      {-5.0, 0.6, 0.0, -2.5},    // reversing: |v|
      {5.0, 0.6, 1.0, -1.25},    // the driver's 1 N m of 2: half
      {5.0, 0.6, -2.5, 0.0},     // hands on
  };
  for (const Case& c : cases) {
    Rig r(p, c.speed_mps);
    r.pose(c.pinion_rad, c.torsion_bar_nm);
    ASSERT_NEAR(r.system.torsion_bar_torque_nm(r.state.steering_y, r.state.steering_z),
                c.torsion_bar_nm, 1e-12);
    EXPECT_NEAR(r.return_nm(c.torsion_bar_nm), c.hand_nm, 1e-9)
        << "v " << c.speed_mps << " theta " << c.pinion_rad << " T_tb " << c.torsion_bar_nm;
  }
}

TEST(ActiveReturn, OffWithTheEcusAssistOrTheIgnitionOffOrWithoutItsKeys) {
  SteeringParams p = sedan_steering();
  {
    Rig r(p, 5.0);
    r.inputs.assist_from_input = true;
    r.inputs.assist_input_nm = 0.7;
    r.pose(0.6, 0.0);
    EXPECT_EQ(r.system.assist_torque_nm(r.state.steering_y, r.state.steering_z), 0.7);
  }
  {
    Rig r(p, 5.0);
    r.inputs.ignition_on = false;
    r.pose(0.6, 0.0);
    EXPECT_EQ(r.system.assist_torque_nm(r.state.steering_y, r.state.steering_z), 0.0);
  }
  p.active_return = ActiveReturnParams{};  // no active_return_* keys
  Rig r(p, 5.0);
  r.pose(0.6, 0.0);
  EXPECT_EQ(r.return_nm(0.0), 0.0);
}

// The implicit step's partials of q(1) (the rack's force) in the rack travel and speed include the
// return's slope T_max / theta_sat / i_SB^2 and damping d / i_SB^2, and in the twist the fade's
// slope d T_r / d T_tb beside the boost curve's: finite differences and hand values agree.
TEST(ActiveReturn, PartialsMatchFiniteDifferences) {
  const SteeringParams p = sedan_steering();
  Rig r(p, 5.0);
  r.pose(0.1, 0.2);
  r.state.steering_z << 0.04, 0.04 * p.rack_per_pinion_m_per_rad;  // no twist rate
  Eigen::Vector2d y = r.state.steering_y, z = r.state.steering_z;
  Eigen::Matrix2d jy, jz;
  r.system.force_jacobians(y, z, jy, jz);
  const auto q_of = [&](const Eigen::Vector2d& yy, const Eigen::Vector2d& zz) {
    Eigen::Vector2d q;
    r.system.applied_forces(yy, zz, q);
    return q;
  };
  // the return's own slope and damping: at a fixed twist (wheel and rack moved together) the
  // hands-off weight stays
  const double e = 1e-9;
  Eigen::Vector2d y2 = y, z2 = z;
  y2(1) += e;
  y2(0) += e / p.rack_per_pinion_m_per_rad;  // same twist: the weight stays
  const double slope_fd = (q_of(y2, z)(1) - q_of(y, z)(1)) / e;
  z2(1) += e;
  z2(0) += e / p.rack_per_pinion_m_per_rad;
  const double damping_fd = (q_of(y, z2)(1) - q_of(y, z)(1)) / e;
  const double slope = jy(1, 1) + jy(1, 0) / p.rack_per_pinion_m_per_rad;
  const double damping = jz(1, 1) + jz(1, 0) / p.rack_per_pinion_m_per_rad;
  std::printf("dq_rack/du at fixed twist: %.1f (finite difference %.1f) N/m; d/du': %.1f (%.1f)\n",
              slope, slope_fd, damping, damping_fd);
  EXPECT_NEAR(slope, slope_fd, 1e-4 * std::abs(slope_fd));
  EXPECT_NEAR(damping, damping_fd, 1e-4 * std::abs(damping_fd));
  // and they are the return's: (1 - 0.2 / 2) x 2.5 / 0.3 / i^2, (1 - 0.1) x 0.3 / i^2
  const double i2 = p.rack_per_pinion_m_per_rad * p.rack_per_pinion_m_per_rad;
  EXPECT_NEAR(slope, -0.9 * 2.5 / 0.3 / i2, 1e-6 * 0.9 * 2.5 / 0.3 / i2);
  EXPECT_NEAR(damping, -0.9 * 0.3 / i2, 1e-6 * 0.9 * 0.3 / i2);
  // the twist (the wheel alone): T_tb moves the boost curve, G (1 - tanh^2(G T_tb / T_max)), and
  // the fade, d T_r / d T_tb = f(v) R / T_h with the return before its weight R = T_max theta /
  // theta_sat + d theta' (f(v) = 1 at 5 m/s; theta 0.1 rad, theta' 0.04 rad/s, T_tb 0.2 N m)
  Eigen::Vector2d y3 = y;
  y3(0) += e;
  const double twist_fd = (q_of(y3, z)(1) - q_of(y, z)(1)) / e;
  const double boost = std::tanh(p.assist_gain * 0.2 / p.assist_max_nm);
  const double fade = (2.5 * 0.1 / 0.3 + 0.3 * 0.04) / 2.0;
  const double twist_hand = p.torsion_bar_stiffness_nmpr *
                            (1 + p.assist_gain * (1 - boost * boost) + fade) /
                            p.rack_per_pinion_m_per_rad;
  std::printf("dq_rack/dphi: %.1f (finite difference %.1f, hand %.1f) N/rad\n", jy(1, 0), twist_fd,
              twist_hand);
  EXPECT_NEAR(jy(1, 0), twist_fd, 1e-4 * std::abs(twist_fd));
  EXPECT_NEAR(jy(1, 0), twist_hand, 1e-9 * twist_hand);
}

// Released (torque input, hand 0) at 20 km/h from 1.5 rad, no tire load: the return torque turns
// the wheel back until it no longer beats the rack's friction, T_max |theta| / theta_sat <= i_SB
// F_c (+ the column's), i.e. inside |theta| <= 0.3 x 0.008125 x 150 / 2.5 = 0.146 rad, where it
// sticks. Without the tires' damping it may swing past the centre, but not out of the band.
TEST(ActiveReturn, ReleasedWheelComesToRestInsideTheStickBand) {
  SteeringParams p = sedan_steering();
  p.torque_input = true;
  Rig r(p, 20.0 / 3.6);
  r.pose(1.5, 0.0);
  const double band_rad = p.active_return.saturation_angle_rad *
                          (p.rack_per_pinion_m_per_rad * p.rack_friction_n + p.column_friction_nm) /
                          p.active_return.torque_max_nm;
  EXPECT_NEAR(band_rad, 0.1463, 1e-4);
  double min_theta = 1.5;
  for (int n = 0; n < 5000; ++n) {
    r.system.begin_step(1e-3);
    r.stepper.advance(1e-3);
    min_theta = std::min(min_theta, r.state.steering_y(1) / p.rack_per_pinion_m_per_rad);
  }
  const double theta = r.state.steering_y(1) / p.rack_per_pinion_m_per_rad;
  std::printf("released at 20 km/h, no tire load: rests at %.4f rad (stick band %.4f rad)\n", theta,
              band_rad);
  EXPECT_EQ(r.state.steering_z(1), 0.0);
  EXPECT_LE(std::abs(theta), band_rad + 1e-9);
  EXPECT_GT(min_theta, -band_rad);
}

}  // namespace
}  // namespace rig::model::vehicle
