// Stick-predicted dry friction in the column steering (rack_friction_n, column_friction_nm):
// no creep of a lightly loaded rack at stand-still, and the hand-torque hysteresis of a slow
// sine with the assist off against its hand value. The SimpleSteering block on its own stepper
// with the tie rods' force set by the test (no tires: the load is exactly known).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

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
  // the framework's speeds at rest (the EPS's active return reads the vehicle's speed: 0 here)
  explicit Rig(const SteeringParams& params) : p(params) { state.framework_z.setZero(10); }
  SteeringParams p;
  VehicleState state;
  VehicleInputs inputs;
  VehicleWorkspace work;
  ColumnSteering system{p, state, inputs};
  SimpleSteering block{system, state, work};
  solver::MechanicalStepper<2> stepper{block};
  void step(double h) {
    system.begin_step(h);
    Eigen::internal::set_is_malloc_allowed(false);
    stepper.advance(h);
    Eigen::internal::set_is_malloc_allowed(true);
  }
};

// Wheel released (torque input, hand 0), assist on, a 100 N tie-rod load below the 150 N rack
// friction, 5 s at 1 ms: the rack's speed is exactly 0 every step and it keeps its travel. (The
// regularised law F_c tanh(z / 2 mm/s) crept at atanh(100 / 150) 2 mm/s = 1.6 mm/s: 8 mm in 5 s.)
TEST(SteeringFriction, RackLoadBelowFrictionDoesNotCreepAtStandstill) {
  SteeringParams p = sedan_steering();
  p.torque_input = true;
  ASSERT_EQ(p.rack_friction_n, 150.0);
  Rig r(p);
  r.state.steering_y << 0.02, 0.02 * p.rack_per_pinion_m_per_rad;  // no twist
  r.work.rack_force_n = 100.0;
  const Eigen::Vector2d y0 = r.state.steering_y;
  for (int n = 0; n < 5000; ++n) {
    r.step(1e-3);
    ASSERT_EQ(r.state.steering_z(1), 0.0) << n;
    ASSERT_EQ(r.state.steering_y(1), y0(1)) << n;
    ASSERT_NEAR(r.state.steering_y(0), y0(0), 1e-12) << n;
  }
  // above the capacity it moves, the friction at exactly its capacity against the motion (the
  // rack's one contact: column_friction_nm 0 declares none)
  r.work.rack_force_n = 200.0;
  r.step(1e-3);
  EXPECT_LT(r.state.steering_z(1), 0.0);
  ASSERT_EQ(r.stepper.friction_contacts().size(), 1);
  EXPECT_EQ(r.stepper.friction_solution().state[0], solver::FrictionState::kSlideNegative);
  EXPECT_EQ(r.stepper.friction_solution().force[0], 150.0);
}

// Slow sine of the steering robot (0.5 rad, 10 s period), assist off (ignition off), no column
// damping, column friction 0.5 N m, no tire load: the hand torque crossing the centre going up
// minus going down is 2 (i_SB F_rack,c + T_column,c) = 2 (0.008125 x 150 + 0.5) = 3.4375 N m
// (the torsion bar carries the rack's friction to the pinion 1:1, the column's adds at the
// wheel; the inertia terms vanish at the centre where the angular acceleration is 0).
TEST(SteeringFriction, HysteresisWidthIsTwiceRackFrictionReflectedPlusColumnFriction) {
  SteeringParams p = sedan_steering();
  p.torque_input = false;
  p.column_damping_nmspr = 0.0;
  p.column_friction_nm = 0.5;
  Rig r(p);
  r.inputs.ignition_on = false;
  const double h = 1e-3, amplitude = 0.5, period = 10.0;
  const double expected = 2 * (p.rack_per_pinion_m_per_rad * p.rack_friction_n + 0.5);
  double up = 0, down = 0, prev_angle = 0, prev_torque = 0;
  int ups = 0, downs = 0;
  for (int n = 0; n < static_cast<int>(2 * period / h); ++n) {
    const double t = n * h;
    r.inputs.steering_angle_cmd_rad = amplitude * std::sin(2 * std::numbers::pi * t / period);
    r.step(h);
    const double angle = r.state.steering_y(0);
    // the robot's torque on the wheel is the hand torque
    const double torque = p.robot_stiffness_nmpr * (r.inputs.steering_angle_cmd_rad - angle) -
                          p.robot_damping_nmspr * r.state.steering_z(0);
    if (t > period / 2 && (prev_angle < 0) != (angle < 0)) {  // centre crossing: interpolate
      const double at_zero =
          prev_torque + (torque - prev_torque) * prev_angle / (prev_angle - angle);
      if (angle > prev_angle) {
        up += at_zero;
        ++ups;
      } else {
        down += at_zero;
        ++downs;
      }
    }
    prev_angle = angle;
    prev_torque = torque;
  }
  ASSERT_GE(ups, 1);
  ASSERT_GE(downs, 1);
  const double width = up / ups - down / downs;
  std::printf("hysteresis at the centre: up %.4f N m, down %.4f N m, width %.4f (hand %.4f)\n",
              up / ups, down / downs, width, expected);
  EXPECT_NEAR(width, expected, 0.01 * expected);
  EXPECT_NEAR(up / ups, -down / downs, 0.01 * expected);  // symmetric
}

// [steering] column_friction_nm: read (default 0 without it), a negative value refused with the
// key's name; the deprecated rack_friction_speed_mps still loads.
TEST(SteeringFriction, ColumnFrictionKeyReadAndChecked) {
  std::ifstream in(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
  std::stringstream text;
  text << in.rdbuf();
  const std::string sedan = text.str();
  const std::string key = "column_friction_nm = 0.0";
  ASSERT_NE(sedan.find(key), std::string::npos);
  ASSERT_NE(sedan.find("rack_friction_speed_mps = 0.002"), std::string::npos);
  const auto load_with = [&](const std::string& line) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / "rig_steering_friction_test.toml";
    std::string edited = sedan;
    edited.replace(edited.find(key), key.size(), line);
    std::ofstream(file) << edited;
    struct Remove {
      std::filesystem::path f;
      ~Remove() { std::filesystem::remove(f); }
    } remove{file};
    return io::config::load_vehicle_file(file).steering;
  };
  EXPECT_EQ(load_with("column_friction_nm = 0.7").column_friction_nm, 0.7);
  EXPECT_EQ(load_with("").column_friction_nm, 0.0);
  try {
    (void)load_with("column_friction_nm = -0.1");
    ADD_FAILURE() << "a negative column friction loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("column_friction_nm"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rig::model::vehicle
