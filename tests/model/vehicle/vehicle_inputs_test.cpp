// The model's inputs of issue 14 (model/signals.h slots): per-wheel brake pressures and the
// units' brake circuits, the steering overlay (simple overriding gear), the ignition, and what
// the report says was applied. Through model::Signals slots directly.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/tire/tmeasy_tire.h"
#include "model/vehicle/drivetrain.h"
#include "model/vehicle/vehicle_model.h"
#include "model/vehicle/vehicle_signals.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::vehicle {
namespace {

VehicleParams sedan() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
}

void set_slot(Signals& s, std::size_t slot, double v) {
  s.value[slot] = v;
  s.valid[slot] = true;
}

// ---- read_inputs: which pressure each wheel gets ----

TEST(BrakeInputs, UnroutedWheelsFollowTheirAxlesCircuit) {
  const VehicleParams p = sedan();  // front axle: front circuit, rear axle: rear circuit
  Signals s = test::all_driver_inputs();
  s[Signal::kBrakePressureFront] = 2e6;
  s[Signal::kBrakePressureRear] = 1e6;
  for (int unit = 0; unit < kMaxUnits; ++unit) {  // a unit without its own slots: the enum's
    const VehicleInputs in = read_inputs(p, unit, s);
    EXPECT_EQ(in.brake_pressure_pa[0], 2e6);
    EXPECT_EQ(in.brake_pressure_pa[1], 2e6);
    EXPECT_EQ(in.brake_pressure_pa[2], 1e6);
    EXPECT_EQ(in.brake_pressure_pa[3], 1e6);
  }
}

TEST(BrakeInputs, AValidWheelPressureReplacesItsCircuitForThatWheelOnly) {
  const VehicleParams p = sedan();
  Signals s = test::all_driver_inputs();
  s[Signal::kBrakePressureFront] = 2e6;
  s[Signal::kBrakePressureRear] = 1e6;
  set_slot(s, wheel_brake_slot(0, 1), 3e6);  // FR modulated up
  set_slot(s, wheel_brake_slot(0, 2), 0.0);  // RL released (ESC pressure reduction)
  const VehicleInputs in = read_inputs(p, 0, s);
  EXPECT_EQ(in.brake_pressure_pa[0], 2e6);
  EXPECT_EQ(in.brake_pressure_pa[1], 3e6);
  EXPECT_EQ(in.brake_pressure_pa[2], 0.0);
  EXPECT_EQ(in.brake_pressure_pa[3], 1e6);
  // another unit's slots do not touch unit 0
  const VehicleInputs other = read_inputs(p, 1, s);
  EXPECT_EQ(other.brake_pressure_pa[1], 2e6);
  EXPECT_EQ(other.brake_pressure_pa[2], 1e6);
}

TEST(BrakeInputs, NonFiniteFallsBackNegativeClampsToZero) {
  const VehicleParams p = sedan();
  Signals s = test::all_driver_inputs();
  s[Signal::kBrakePressureFront] = 2e6;
  s[Signal::kBrakePressureRear] = -5e5;  // clamped, as today
  set_slot(s, wheel_brake_slot(0, 0), std::numeric_limits<double>::quiet_NaN());
  set_slot(s, wheel_brake_slot(0, 3), -1e6);
  const VehicleInputs in = read_inputs(p, 0, s);
  EXPECT_EQ(in.brake_pressure_pa[0], 2e6);  // NaN: its circuit
  EXPECT_EQ(in.brake_pressure_pa[2], 0.0);  // rear circuit clamped
  EXPECT_EQ(in.brake_pressure_pa[3], 0.0);  // wheel clamped
}

TEST(BrakeInputs, AUnitsOwnCircuitReplacesTheEnumsForThatUnit) {
  const VehicleParams p = sedan();
  Signals s = test::all_driver_inputs();
  s[Signal::kBrakePressureFront] = 2e6;
  s[Signal::kBrakePressureRear] = 1e6;
  set_slot(s, brake_circuit_slot(2, 1), 4e6);  // unit 2's rear circuit
  const VehicleInputs u2 = read_inputs(p, 2, s);
  EXPECT_EQ(u2.brake_pressure_pa[0], 2e6);  // its front circuit not valid: the enum's
  EXPECT_EQ(u2.brake_pressure_pa[2], 4e6);
  EXPECT_EQ(u2.brake_pressure_pa[3], 4e6);
  const VehicleInputs u1 = read_inputs(p, 1, s);
  EXPECT_EQ(u1.brake_pressure_pa[2], 1e6);
}

TEST(OtherInputs, OverlayAndIgnitionDefaultsAndStates) {
  const VehicleParams p = sedan();
  Signals s{};  // nothing valid
  VehicleInputs in = read_inputs(p, 0, s);
  EXPECT_EQ(in.overlay_angle_rad, 0.0);
  EXPECT_TRUE(in.ignition_on);  // not valid: on
  s.set(Signal::kSteeringOverlayAngleCmd, 0.1);
  EXPECT_EQ(read_inputs(p, 0, s).overlay_angle_rad, 0.1);
  for (const double state : {0.0, 1.0, 2.0, 3.0}) {
    s.set(Signal::kIgnition, state);
    EXPECT_EQ(read_inputs(p, 0, s).ignition_on, state >= 2.0) << state;
  }
  s.set(Signal::kIgnition, std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(read_inputs(p, 0, s).ignition_on);
}

// ---- steering overlay ----

struct OverlayResult {
  double rack_m, expected_m, tb_nm, rack_force_n, wheel_rad, assist_nm;
};

// Hand wheel held at 0 by the steering robot (angle mode), a 0.1 rad overlay step at t = 0.5 s
// (the gear follows it at its rate limit), 3 s later: the rack at steady state.
OverlayResult hold_wheel_with_overlay(double speed_mps) {
  VehicleParams p = sedan();
  // the gear's kinematics alone: without the bore torque's resistance at stand-still (issue 15),
  // which twists the torsion bar by a further F_rack i_SB / c
  for (AxleParams& a : p.axles) a.tire.tmeasy.bore.enabled = false;
  // nor the built-in EPS's active return, which turns the pinion back against the overlay
  p.steering.active_return = ActiveReturnParams{};
  VehicleModel m(p, 1e-3);
  const VehicleModel::Equilibrium e = m.settle(speed_mps, speed_mps > 0 ? 99 : 0);
  Signals s = test::all_driver_inputs();
  s[Signal::kGearRequest] = speed_mps > 0 ? 99 : 0;
  s[Signal::kThrottlePedal] = e.throttle;
  while (m.time_s() < 3.5) {
    s[Signal::kSteeringOverlayAngleCmd] = m.time_s() < 0.5 ? 0.0 : 0.1;
    EXPECT_EQ(m.step(s), StepStatus::kOk);
  }
  const double i_sb = p.steering.rack_per_pinion_m_per_rad;
  ModelReport r;
  m.fill_report(r);
  return {r.steering.rack_travel_m,         0.1 * i_sb,
          r.steering.torsion_bar_torque_nm, r.steering.rack_force_n,
          r.steering.wheel_angle_rad,       r.steering.assist_torque_nm};
}

// Steady state: the rack sticks where (T_tb + T_a(T_tb)) / i_SB = F_rack + lambda, |lambda| <=
// rack_friction_n (stick-predicted dry friction holds the rest), and
// T_tb = c (delta_wheel - u / i_SB + overlay), so u = i_SB (overlay + delta_wheel - T_tb / c):
// the overlay times i_SB less the torsion bar's twist that carries the tires' rack force, the
// friction's hold and the EPS's active return T_r, which pulls the pinion back towards the
// centre at 2 and 10 m/s (small, the assist carries most of it: T_tb <= (i_SB (|F_rack| + F_c) +
// |T_r|) / (1 + G)) plus the robot's give (delta_wheel = -T_tb / k_robot).
TEST(SteeringOverlay, MovesTheRackByOverlayTimesRackRatioWithTheWheelHeld) {
  const VehicleParams p = sedan();
  const double c = p.steering.torsion_bar_stiffness_nmpr;
  const double i_sb = p.steering.rack_per_pinion_m_per_rad;
  for (const double v : {0.0, 2.0, 10.0}) {
    const OverlayResult o = hold_wheel_with_overlay(v);
    const double twist_m = i_sb * (o.wheel_rad - o.tb_nm / c);
    std::printf(
        "overlay 0.1 rad at %.0f m/s: rack %.4e m, 0.1 i_SB %.4e m (%+.2f %%); T_tb %.4f N m, "
        "F_rack %.1f N, wheel %.2e rad; i_SB (delta - T_tb/c) %.3e m explains %.3e m\n",
        v, o.rack_m, o.expected_m, 100 * (o.rack_m / o.expected_m - 1), o.tb_nm, o.rack_force_n,
        o.wheel_rad, twist_m, o.rack_m - o.expected_m);
    const double f_c = p.steering.rack_friction_n;
    const double k_robot = p.steering.robot_stiffness_nmpr;
    EXPECT_LE(std::abs((o.tb_nm + o.assist_nm) / i_sb - o.rack_force_n), f_c * (1 + 1e-9));
    // T_r: the EPS's torque less its boost curve's share at T_tb
    const double return_nm =
        o.assist_nm - p.steering.assist_max_nm *
                          std::tanh(p.steering.assist_gain * o.tb_nm / p.steering.assist_max_nm);
    const double tb_max_nm = (i_sb * (std::abs(o.rack_force_n) + f_c) + std::abs(return_nm)) /
                             (1 + p.steering.assist_gain);
    EXPECT_NEAR(o.rack_m, o.expected_m, i_sb * tb_max_nm * (1 / c + 1 / k_robot));
    EXPECT_NEAR(o.rack_m - o.expected_m, twist_m, 1e-3 * o.expected_m);
  }
}

// ---- steering robot release (returnability) ----

// With the angle routed (angle_from_input), the robot lets go while the angle is not valid (or
// not finite); not routed, it holds the wheel at 0 as before (the release's dynamics:
// config/maneuvers/returnability.toml, tests/integration/maneuver_test.py).
TEST(SteeringRobot, LetsGoOfTheWheelWhileARoutedAngleIsNotValid) {
  VehicleParams p = sedan();
  Signals s = test::all_driver_inputs();
  const std::size_t angle = index(Signal::kSteeringWheelAngleCmd);
  s.valid[angle] = false;
  EXPECT_FALSE(read_inputs(p, 0, s).robot_released);  // not routed: holds at 0
  p.steering.angle_from_input = true;
  EXPECT_TRUE(read_inputs(p, 0, s).robot_released);
  set_slot(s, angle, 0.3);
  EXPECT_FALSE(read_inputs(p, 0, s).robot_released);
  s.value[angle] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(read_inputs(p, 0, s).robot_released);
}

// ---- ignition ----

// Ignition off at 20 m/s with the throttle pressed and a steady steering angle: the engine only
// drags (torque = -drag at its speed, the throttle ignored), the assist is 0 and the torsion bar
// carries the whole rack force, T_tb = i_SB F_rack (the rack's steady balance without assist),
// against T_tb + T_a = i_SB F_rack with it on; both up to the stuck rack's dry friction,
// |T_tb - i_SB F_rack| <= i_SB rack_friction_n (1.22 N m; measured 0.85 N m).
TEST(Ignition, OffAtSpeedNoEngineTorqueNoAssist) {
  const VehicleParams p = sedan();
  const double i_sb = p.steering.rack_per_pinion_m_per_rad;
  double tb_on = 0;
  for (const double ignition : {2.0, 0.0}) {
    VehicleModel m(p, 1e-3);
    const VehicleModel::Equilibrium e = m.settle(20.0);
    Signals s = test::all_driver_inputs();
    s[Signal::kThrottlePedal] = ignition == 0 ? 0.5 : e.throttle;
    s[Signal::kIgnition] = ignition;
    s[Signal::kSteeringWheelAngleCmd] = 0.5;
    while (m.time_s() < 2.0) ASSERT_EQ(m.step(s), StepStatus::kOk);
    ModelReport r;
    m.fill_report(r);
    const double we = r.drivetrain.engine_speed_radps;
    const double tb = r.steering.torsion_bar_torque_nm, f = r.steering.rack_force_n;
    std::printf(
        "ignition %.0f at %.1f m/s: engine %.1f rad/s, torque %.3f N m (-drag %.3f), assist "
        "%.3f N m, T_tb %.4f N m, i_SB F_rack %.4f N m\n",
        ignition, m.state().framework_z(0), we, r.drivetrain.engine_torque_nm,
        -engine_drag_nm(p.drivetrain, we), r.steering.assist_torque_nm, tb, i_sb * f);
    if (ignition == 2.0) {
      tb_on = tb;
      EXPECT_GT(r.steering.assist_torque_nm, 0.5);
      continue;
    }
    EXPECT_DOUBLE_EQ(r.drivetrain.engine_torque_nm, -engine_drag_nm(p.drivetrain, we));
    EXPECT_LT(r.drivetrain.engine_torque_nm, 0.0);
    EXPECT_EQ(r.steering.assist_torque_nm, 0.0);
    EXPECT_LE(std::abs(tb - i_sb * f), i_sb * p.steering.rack_friction_n * (1 + 1e-9));
    EXPECT_GT(tb, 2 * tb_on);  // the assist carried most of it
  }
}

// ---- one-sided braking ----

// The sedan at 20 m/s straight, throttle 0, 30 bar on the left wheels only (their wheel slots):
// the left brake forces pull the car to the left, a positive yaw rate (z up). A wheel's brake
// torque (WheelReport) is its brake plus its rolling resistance f_r F_z r (wheel_spin.cpp, one
// dry friction): the right wheels' is the rolling resistance alone, the left wheels' gain x p
// more while they roll.
TEST(OneSidedBraking, SedanLeftWheelsYawLeftRightWheelsUnbraked) {
  const VehicleParams p = sedan();
  VehicleModel m(p, 1e-3);
  (void)m.settle(20.0);
  Signals s = test::all_driver_inputs();
  s[Signal::kThrottlePedal] = 0.0;
  set_slot(s, wheel_brake_slot(0, 0), 3e6);
  set_slot(s, wheel_brake_slot(0, 2), 3e6);
  std::array<double, 4> brake_only{};  // worst |brake torque - rolling resistance - gain p|
  double yaw_05 = 0;
  ModelReport r;
  while (m.time_s() < 1.0) {
    ASSERT_EQ(m.step(s), StepStatus::kOk);
    m.fill_report(r);
    for (std::size_t k = 0; k < 4; ++k) {
      const AxleParams& axle = p.axles[k / 2];
      const WheelWork& w = m.workspace().wheels[k];
      const double rolling = tire::rolling_resistance_torque_nm(axle.tire.tmeasy, w.load_n,
                                                                w.tire.kinematics.rolling_radius_m);
      const double brake = k % 2 == 0 ? axle.brake_gain_nm_per_pa * 3e6 : 0.0;
      brake_only[k] =
          std::max(brake_only[k],
                   std::abs(std::abs(r.units[0].wheels[k].brake_torque_nm) - rolling - brake));
    }
    if (std::abs(m.time_s() - 0.5) < 5e-4) yaw_05 = s[Signal::kYawRate];
  }
  const auto& w = r.units[0].wheels;
  std::printf(
      "30 bar left wheels at 20 m/s: yaw rate %.4f rad/s at 0.5 s, %.4f rad/s at 1 s "
      "(speed %.2f m/s, a_y %.3f m/s^2); brake torque FL %.1f FR %.1f RL %.1f RR %.1f N m "
      "(gain x p %.1f, %.1f); worst brake torque - rolling resistance - gain x p %.2g N m\n",
      yaw_05, s[Signal::kYawRate], m.state().framework_z(0), s[Signal::kLateralAccel],
      w[0].brake_torque_nm, w[1].brake_torque_nm, w[2].brake_torque_nm, w[3].brake_torque_nm,
      p.axles[0].brake_gain_nm_per_pa * 3e6, p.axles[1].brake_gain_nm_per_pa * 3e6,
      *std::max_element(brake_only.begin(), brake_only.end()));
  EXPECT_GT(yaw_05, 0.0);
  EXPECT_GT(s[Signal::kYawRate], 0.0);
  EXPECT_EQ(s[Signal::kYawRate], r.units[0].angular_velocity_radps[2]);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_LT(brake_only[k], 1e-9) << "wheel " << k;
  EXPECT_EQ(w[0].brake_pressure_pa, 3e6);
  EXPECT_EQ(w[1].brake_pressure_pa, 0.0);
  EXPECT_EQ(w[2].brake_pressure_pa, 3e6);
  EXPECT_EQ(w[3].brake_pressure_pa, 0.0);
  EXPECT_EQ(s[Signal::kBrakePressureFL], 3e6);
  EXPECT_EQ(s[Signal::kBrakePressureFR], 0.0);
  EXPECT_EQ(r.brake_pressure_pa[2], 3e6);
  EXPECT_EQ(r.steering.wheel_speed_radps, s[Signal::kSteeringWheelSpeed]);
}

}  // namespace
}  // namespace rig::model::vehicle
