// A combination's per-unit inputs (issue 14, model/signals.h): each unit reads its own block of
// slots, so a trailer's own wheel slot brakes only that wheel and a unit's own circuit only that
// unit; unrouted, every unit's axles follow the enum's circuits (today's behaviour).
#include <cmath>
#include <cstdio>
#include <utility>

#include <gtest/gtest.h>

#include "model/combination/combination.h"
#include "model/tire/tmeasy_tire.h"
#include "tests/support/combination_files.h"
#include "tests/support/driver_inputs.h"

namespace rig::model::combination {
namespace {

void set_slot(Signals& s, std::size_t slot, double v) {
  s.value[slot] = v;
  s.valid[slot] = true;
}

// 0.3 s at 15 m/s in neutral with the given inputs; the report at its end.
ModelReport run(Combination& c, const Signals& inputs) {
  Signals s = inputs;
  while (c.time_s() < 0.3) EXPECT_EQ(c.step(s), StepStatus::kOk);
  ModelReport r;
  c.fill_report(r);
  return r;
}

// A wheel's brake torque less its rolling resistance f_r F_z r: the part its brake pressure
// gives (WheelReport::brake_torque_nm holds both, one dry friction in wheel_spin.cpp).
double brake_part_nm(Combination& c, const ModelReport& r, int unit, int wheel) {
  const auto k = static_cast<std::size_t>(wheel);
  const vehicle::VehicleModel& u = c.unit(unit);
  const vehicle::WheelWork& w = u.workspace().wheels[k];
  const double rolling = tire::rolling_resistance_torque_nm(
      u.params().axles[k / 2].tire.tmeasy, w.load_n, w.tire.kinematics.rolling_radius_m);
  return std::abs(r.units[static_cast<std::size_t>(unit)].wheels[k].brake_torque_nm) - rolling;
}

Signals coasting() {
  Signals s = test::all_driver_inputs();
  s[Signal::kGearRequest] = 0;
  return s;
}

TEST(CombinationInputs, TrailersOwnWheelSlotBrakesOnlyThatWheel) {
  // pressures below the trailer wheel's lock (the semitrailer's brakes give 1.67e-2 N m/Pa)
  for (const auto& [file, pressure_pa] :
       {std::pair{test::kCarTrailer, 2e6}, std::pair{test::kTractorSemi, 3e5}}) {
    Combination c(test::load_combination(file), 1e-3);
    ASSERT_EQ(c.unit(1).unit_index(), 1);
    c.set_forward_speed(15.0);
    Signals s = coasting();
    set_slot(s, wheel_brake_slot(1, 0), pressure_pa);  // the trailer's first left wheel
    const ModelReport r = run(c, s);
    const double gain = c.unit(1).params().axles[0].brake_gain_nm_per_pa;
    const WheelReport& braked = r.units[1].wheels[0];
    std::printf(
        "%s: trailer wheel 0 at %.0f bar: brake torque %.1f N m, less rolling resistance %.3f N m "
        "(gain x p %.1f)\n",
        file, pressure_pa / 1e5, braked.brake_torque_nm, brake_part_nm(c, r, 1, 0),
        gain * pressure_pa);
    EXPECT_NEAR(brake_part_nm(c, r, 1, 0), gain * pressure_pa, 1e-6);
    EXPECT_EQ(braked.brake_pressure_pa, pressure_pa);
    for (int u = 0; u < r.unit_count; ++u) {
      const UnitReport& unit = r.units[static_cast<std::size_t>(u)];
      for (int w = 0; w < unit.wheel_count; ++w) {
        if (u == 1 && w == 0) continue;
        const WheelReport& wheel = unit.wheels[static_cast<std::size_t>(w)];
        EXPECT_NEAR(brake_part_nm(c, r, u, w), 0.0, 1e-9)
            << file << " unit " << u << " wheel " << w;
        EXPECT_EQ(wheel.brake_pressure_pa, 0.0) << file << " unit " << u << " wheel " << w;
      }
    }
  }
}

TEST(CombinationInputs, UnitCircuitBrakesThatUnitUnroutedFollowsTheEnum) {
  Combination c(test::load_combination(test::kTractorSemi), 1e-3);
  c.set_forward_speed(15.0);
  Signals s = coasting();
  s[Signal::kBrakePressureRear] = 5e5;         // the enum's rear circuit (tractor, unit 0)
  set_slot(s, brake_circuit_slot(1, 1), 2e5);  // the semitrailer's own rear circuit
  set_slot(s, wheel_brake_slot(1, 3), 4e5);    // ... and its second axle's right wheel
  const ModelReport r = run(c, s);
  const UnitReport& tractor = r.units[0];
  const UnitReport& semi = r.units[1];
  EXPECT_EQ(tractor.wheels[0].brake_pressure_pa, 0.0);  // front circuit
  for (int w = 2; w < tractor.wheel_count; ++w)
    EXPECT_EQ(tractor.wheels[static_cast<std::size_t>(w)].brake_pressure_pa, 5e5);
  for (int w = 0; w < semi.wheel_count; ++w) {
    const WheelReport& wheel = semi.wheels[static_cast<std::size_t>(w)];
    EXPECT_EQ(wheel.brake_pressure_pa, w == 3 ? 4e5 : 2e5) << w;
    const double gain =
        c.unit(1).params().axles[static_cast<std::size_t>(w / 2)].brake_gain_nm_per_pa;
    EXPECT_NEAR(brake_part_nm(c, r, 1, w), gain * wheel.brake_pressure_pa, 1e-6) << w;
  }
  // the same without the semitrailer's slots: its axles (rear circuit) follow the enum's rear
  Combination d(test::load_combination(test::kTractorSemi), 1e-3);
  d.set_forward_speed(15.0);
  Signals t = coasting();
  t[Signal::kBrakePressureRear] = 5e5;
  const ModelReport q = run(d, t);
  for (int w = 0; w < q.units[1].wheel_count; ++w)
    EXPECT_EQ(q.units[1].wheels[static_cast<std::size_t>(w)].brake_pressure_pa, 5e5) << w;
}

}  // namespace
}  // namespace rig::model::combination
