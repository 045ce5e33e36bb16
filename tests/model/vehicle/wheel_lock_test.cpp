// Locked wheels (issue 12, part 3): a wheel that its brake holds reports 0 until the brake
// releases; a fully sliding tire transmits the characteristic's sliding force F_S, not F_M.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "io/config/vehicle_file.h"
#include "model/tire/tmeasy_tire.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::vehicle {
namespace {

VehicleParams sedan() {
  return io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/sedan.toml");
}

// All four wheels locked from 22 m/s on a flat dry road, in neutral: between 20 and 5 m/s the
// mean deceleration is (sum F_S(F_z) + drag + rolling resistance) / m within 3 %, with F_z the
// loads the model reports and F_S the sliding value of each tire's characteristic.
TEST(LockedWheels, AllLockedStopDeceleratesWithTheSlidingForce) {
  const VehicleParams p = sedan();
  VehicleModel m(p, 1e-3);
  m.set_forward_speed(22.0);
  Signals s = test::all_driver_inputs();
  s[Signal::kGearRequest] = 0;  // neutral: no engine braking
  s[Signal::kBrakePressureFront] = 2e7;
  s[Signal::kBrakePressureRear] = 2e7;
  const double mass = m.framework().total_mass_kg();
  const road::Road road(p.road);
  double t_20 = -1, t_5 = -1, ref_sum = 0, ref_no_rr_sum = 0;
  long ref_n = 0, spinning = 0;
  while (m.time_s() < 10.0 && t_5 < 0) {
    ASSERT_EQ(m.step(s), StepStatus::kOk);
    const double v = m.state().framework_z(0);
    if (t_20 < 0 && v <= 20.0) t_20 = m.time_s();
    if (t_20 >= 0 && v <= 5.0) t_5 = m.time_s();
    if (t_20 < 0) continue;
    double sliding = 0, rolling = 0;
    for (int i = 0; i < 4; ++i) {
      const double fz = m.wheel_load_n(i);
      const tire::TmeasyParams& t = p.axles[static_cast<std::size_t>(i / 2)].tire.tmeasy;
      sliding += tire::characteristic_at(t, fz, road.friction(i % 2 == 1)).x.slide_force_n;
      rolling += t.rolling_resistance * fz;
      spinning += std::abs(m.state().spin_radps[static_cast<std::size_t>(i)]) > 0.01 ? 1 : 0;
    }
    const double drag = 0.5 * p.chassis.air_density_kgpm3 * p.chassis.drag_area_m2 * v * v;
    ref_sum += (sliding + drag + rolling) / mass;
    ref_no_rr_sum += (sliding + drag) / mass;
    ++ref_n;
  }
  ASSERT_GT(t_5, t_20);
  const double decel = 15.0 / (t_5 - t_20);
  const double ref = ref_sum / static_cast<double>(ref_n);
  std::printf(
      "all wheels locked 20 -> 5 m/s: %.3f m/s^2; (sum F_S + drag + f_r F_z)/m = %.3f m/s^2 "
      "(%+.2f %%), without rolling resistance %.3f m/s^2\n",
      decel, ref, 100 * (decel / ref - 1), ref_no_rr_sum / static_cast<double>(ref_n));
  EXPECT_EQ(spinning, 0);  // every wheel held at 0 throughout
  EXPECT_NEAR(decel, ref, 0.03 * ref);
}

// Straight braking on split mu (left 1.0, right 0.2): the right wheels lock and must read 0
// (within 0.01 rad/s) from their lock until the brakes release - what an ESC sees.
TEST(LockedWheels, HeldWheelReportsZeroUntilTheBrakeReleases) {
  VehicleParams p = sedan();
  p.road.friction_right = 0.2;
  VehicleModel m(p, 1e-3);
  m.set_forward_speed(22.0);
  Signals s = test::all_driver_inputs();
  s[Signal::kGearRequest] = 0;
  std::array<bool, 4> locked{};
  std::array<double, 4> worst{};
  long held_steps = 0;
  while (m.time_s() < 2.5) {
    const bool braking = m.time_s() < 2.0;
    s[Signal::kBrakePressureFront] = braking ? 5e6 : 0.0;
    s[Signal::kBrakePressureRear] = braking ? 2.5e6 : 0.0;
    ASSERT_EQ(m.step(s), StepStatus::kOk);
    if (!braking) break;
    for (int i : {1, 3}) {  // the low-mu side
      const double w = m.state().spin_radps[static_cast<std::size_t>(i)];
      if (w == 0.0) locked[static_cast<std::size_t>(i)] = true;
      if (locked[static_cast<std::size_t>(i)]) {
        worst[static_cast<std::size_t>(i)] =
            std::max(worst[static_cast<std::size_t>(i)], std::abs(w));
        ++held_steps;
      }
    }
  }
  std::printf(
      "split mu: right wheels locked %d / %d, held steps %ld, max |w| after lock %.4f / %.4f "
      "rad/s\n",
      locked[1], locked[3], held_steps, worst[1], worst[3]);
  EXPECT_TRUE(locked[1] && locked[3]);
  EXPECT_GT(held_steps, 1000);
  EXPECT_LT(worst[1], 0.01);
  EXPECT_LT(worst[3], 0.01);
}

}  // namespace
}  // namespace rig::model::vehicle
