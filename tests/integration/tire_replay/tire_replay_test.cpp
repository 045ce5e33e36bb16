// model/tire's law against what the rig logged: `rig run --offline --lcm-log` of the demo (the
// sedan's lane change, braking to stand-still on a grade and holding) and of the paper's quarter
// car (driving, locked wheel, held on the grade); for every logged wheel state, model/tire's
// characteristic_at + slip_of + tire_forces at the logged tire inputs (v_x, v_y, omega, r_D, the
// characteristic's F_z, the road's mu, x_e, y_e) give the logged wheel forces bit for bit.
#include <lcm/eventlog.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/tire/tmeasy_tire.h"
#include "rig/config.h"
#include "rig/vehicle_state_t.hpp"

namespace rig {
namespace {

/// Runs the configuration offline and returns its RIG_STATE messages.
std::vector<vehicle_state_t> logged_states(const std::string& config, const std::string& name) {
  const std::string log = ::testing::TempDir() + "/tire_replay_" + name + ".lcm";
  const std::string cmd = std::string(RIG_BIN) + " run --config " + config +
                          " --offline --can none --lcm-url none --lcm-log " + log + " 2>/dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::vector<vehicle_state_t> out;
  lcm_eventlog_t* f = lcm_eventlog_create(log.c_str(), "r");
  if (f == nullptr) return out;
  while (lcm_eventlog_event_t* e = lcm_eventlog_read_next_event(f)) {
    if (std::string(e->channel) == "RIG_STATE") {
      vehicle_state_t m;
      if (m.decode(e->data, 0, static_cast<int>(e->datalen)) >= 0) out.push_back(m);
    }
    lcm_eventlog_free_event(e);
  }
  lcm_eventlog_destroy(f);
  return out;
}

/// The forces of model/tire at wheel i of message m.
model::tire::TireForces replayed(const model::tire::TmeasyParams& p, double friction,
                                 const vehicle_state_t& m, int i) {
  const auto k = static_cast<std::size_t>(i);
  const model::tire::TireCharacteristic c =
      model::tire::characteristic_at(p, m.wheel_tire_load_n[k], friction);
  const model::tire::TireKinematics kin{m.wheel_long_speed_mps[k], m.wheel_lat_speed_mps[k],
                                        m.wheel_spin_radps[k], m.wheel_rolling_radius_m[k]};
  const model::tire::TireSlip slip = model::tire::slip_of(c, kin, p.velocity_floor_mps);
  return model::tire::tire_forces(p, c, kin, slip,
                                  Eigen::Vector2d(m.wheel_x_e_m[k], m.wheel_y_e_m[k]));
}

TEST(TireReplay, SedanLoggedWheelForcesBitForBit) {
  // the demo: ISO 3888-1 lane change at 60 km/h, then braking to stand-still on a 10 % grade
  const std::string config = RIG_SOURCE_DIR "/config/rig.toml";
  const RigConfig rc = load_config(config);
  const model::vehicle::VehicleParams& p = rc.model.vehicle->params;
  const model::road::Road road(p.road);
  const std::vector<vehicle_state_t> states = logged_states(config, "sedan");
  ASSERT_GT(states.size(), 10000u);
  long compared = 0, limited = 0, braking = 0;
  for (const vehicle_state_t& m : states) {
    ASSERT_EQ(m.num_wheels, 4);
    for (int i = 0; i < m.num_wheels; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!(m.wheel_load_n[k] > 0)) continue;  // lifted off at the end of the step: no force
      const model::tire::TireForces f =
          replayed(p.axles[k / 2].tire.tmeasy, road.friction(i % 2 == 1), m, i);
      ASSERT_EQ(f.long_force_n, m.wheel_force_x_n[k]) << "cycle " << m.cycle << " wheel " << i;
      ASSERT_EQ(f.lat_force_n, m.wheel_force_y_n[k]) << "cycle " << m.cycle << " wheel " << i;
      ++compared;
      limited += f.limited ? 1 : 0;
      braking += m.wheel_force_x_n[k] < -500 ? 1 : 0;
    }
  }
  std::printf("sedan: %ld wheel states replayed bit for bit (%ld braking, %ld limited)\n", compared,
              braking, limited);
  EXPECT_EQ(compared, 4 * static_cast<long>(states.size()));
  EXPECT_GT(braking, 1000);  // the run brakes, so the longitudinal law is exercised too
}

TEST(TireReplay, QuarterCarLoggedTireForceBitForBit) {
  const std::string config = RIG_SOURCE_DIR "/config/maneuvers/paper-quarter-car.toml";
  const RigConfig rc = load_config(config);
  const std::vector<vehicle_state_t> states = logged_states(config, "quarter_car");
  ASSERT_GT(states.size(), 10000u);
  long compared = 0, limited = 0;
  for (const vehicle_state_t& m : states) {
    ASSERT_EQ(m.num_wheels, 1);
    const model::tire::TireForces f = replayed(rc.model.quarter_car.tire, 1.0, m, 0);
    ASSERT_EQ(f.long_force_n, m.wheel_force_x_n[0]) << "cycle " << m.cycle;
    ++compared;
    limited += f.limited ? 1 : 0;
  }
  std::printf("quarter car: %ld tire states replayed bit for bit (%ld limited)\n", compared,
              limited);
  EXPECT_GT(limited, 100);  // the locked wheel slides on the limit of eq. (26)
}

}  // namespace
}  // namespace rig
