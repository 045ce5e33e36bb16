// The built-in EPS's active return (SteeringParams::active_return, steering/README.md "active
// return"): the torque law against hand values (the pinion angle's slope and saturation, the speed
// trapezoid, the hands-off fade), off with the ECU's assist or the ignition off, its partials
// against finite differences, and a released wheel with no tire load coming to rest inside the
// friction's stick band (hand value from T_max, theta_sat and the rack friction).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

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

// The implicit step's partials of the column's forces include the return's: its slope T_max /
// theta_sat / i_SB^2 and damping d / i_SB^2 on the rack, and its fade with the torsion-bar torque
// (a slope on T_tb, as the boost curve's): all of the 2 x 2 against central finite differences,
// at states in the linear part, saturated, and with the driver's torque of either sign.
TEST(ActiveReturn, PartialsMatchFiniteDifferences) {
  const SteeringParams p = sedan_steering();
  const double i = p.rack_per_pinion_m_per_rad;
  for (const auto& [pinion, twist_nm, rate] :
       {std::tuple{0.1, 0.2, 0.04}, std::tuple{0.1, -0.7, -0.3}, std::tuple{-0.5, 1.2, 0.2},
        std::tuple{0.2, 0.0, 0.0}}) {
    Rig r(p, 15.0);  // on the trapezoid's falling side: f(v) = 0.65
    r.pose(pinion, twist_nm);
    r.state.steering_z << rate + 0.01, rate * i;
    const Eigen::Vector2d y = r.state.steering_y, z = r.state.steering_z;
    Eigen::Matrix2d jy, jz, fy, fz;
    r.system.force_jacobians(y, z, jy, jz);
    const auto q_of = [&](const Eigen::Vector2d& yy, const Eigen::Vector2d& zz) {
      Eigen::Vector2d q;
      r.system.applied_forces(yy, zz, q);
      return q;
    };
    for (int j = 0; j < 2; ++j) {
      const double ey = 1e-7 * (j == 0 ? 1.0 : i), ez = ey;
      Eigen::Vector2d dy = Eigen::Vector2d::Zero(), dz = Eigen::Vector2d::Zero();
      dy(j) = ey;
      dz(j) = ez;
      fy.col(j) = (q_of(y + dy, z) - q_of(y - dy, z)) / (2 * ey);
      fz.col(j) = (q_of(y, z + dz) - q_of(y, z - dz)) / (2 * ez);
    }
    EXPECT_LT((jy - fy).norm(), 1e-6 * fy.norm()) << pinion << " " << twist_nm << "\n"
                                                  << jy << "\n"
                                                  << fy;
    EXPECT_LT((jz - fz).norm(), 1e-6 * fz.norm()) << pinion << " " << twist_nm << "\n"
                                                  << jz << "\n"
                                                  << fz;
  }
  // at a fixed twist (hands-off weight 1 - 0.2 / 2, f(v) = 1 at 5 m/s) the rack's own partials
  // are the return's: 0.9 x 2.5 / 0.3 / i^2 and 0.9 x 0.3 / i^2
  Rig r(p, 5.0);
  r.pose(0.1, 0.2);
  Eigen::Matrix2d jy, jz;
  r.system.force_jacobians(r.state.steering_y, r.state.steering_z, jy, jz);
  const double i2 = i * i;
  EXPECT_NEAR(jy(1, 1) + jy(1, 0) / i, -0.9 * 2.5 / 0.3 / i2, 1e-6 * 0.9 * 2.5 / 0.3 / i2);
  EXPECT_NEAR(jz(1, 1) + jz(1, 0) / i, -0.9 * 0.3 / i2, 1e-6 * 0.9 * 0.3 / i2);
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
