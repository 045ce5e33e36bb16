// Scenario events (rig/driver/scenario_events.h): [[event]] parsing, firing after `for_s` of
// held condition, the ramps and holds of `set`, `stop` through the executive, no allocation.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/config/config_error.h"
#include "io/config/strict_table.h"
#include "rig/driver/scenario_events.h"
#include "rig/event_log.h"
#include "rig/executive.h"
#include "tests/rig/fake_clock.h"
#include "tests/rig/test_model.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/config_error_of.h"

namespace rig::driver {
namespace {

using model::Signal;

std::vector<EventSpec> parse(const std::string& text) {
  const toml::table doc = toml::parse(std::string_view(text), std::string("events.toml"));
  io::config::StrictTable top(doc, "events.toml", "top level");
  auto events = read_events(top, io::signals::Catalogue::two_axle_vehicle());
  top.finish();
  return events;
}

std::string message_of(const std::string& text) {
  return test::config_error_of([&] { parse(text); });
}

/// One cycle's view: the inputs in `s`, the report's x position.
struct View {
  model::Signals s{};
  model::ModelReport r{};
  View() {
    r.valid = 1;
    s.set(Signal::kPositionX, 0.0);
  }
  void x(double x_m) {
    r.units[0].position_m[0] = x_m;
    s.set(Signal::kPositionX, x_m);
  }
  bool update(EventStage& stage, double t) {
    return stage.update(t, io::signals::CycleView{s, r}, s);
  }
};

TEST(ScenarioEvents, ReadsWhenAndDo) {
  const auto e = parse(R"(
[[event]]
name = "step"
when = { signal = "vehicle_speed_mps", op = ">=", value = 16.67 }
do = { set = { steering_wheel_angle_cmd_rad = 0.5, unit1.throttle_pedal = 0.1 }, ramp_s = 0.1 }
[[event]]
when = { signal = "vehicle_speed_mps", op = "<", value = 0.1, for_s = 2.0 }
do = "stop"
)");
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].name, "step");
  EXPECT_EQ(e[0].when.op, CompareOp::kGreaterEqual);
  EXPECT_DOUBLE_EQ(e[0].when.value, 16.67);
  EXPECT_DOUBLE_EQ(e[0].when.for_s, 0.0);
  ASSERT_EQ(e[0].set.size(), 2u);
  EXPECT_EQ(e[0].set[0].slot, model::index(Signal::kSteeringWheelAngleCmd));
  EXPECT_EQ(e[0].set[1].slot, model::index(Signal::kThrottlePedal));  // dotted: nested tables
  EXPECT_DOUBLE_EQ(e[0].ramp_s, 0.1);
  EXPECT_FALSE(e[0].stop);
  EXPECT_EQ(e[1].name, "event1");
  EXPECT_TRUE(e[1].stop);
  EXPECT_DOUBLE_EQ(e[1].when.for_s, 2.0);
  const io::InputSet in = event_inputs(e);
  EXPECT_EQ(in.count(), 2u);
}

TEST(ScenarioEvents, BadInputNamesTheKey) {
  const std::string when =
      "[[event]]\nwhen = { signal = \"vehicle_speed_mps\", op = \">\", value = 1 }\n";
  EXPECT_NE(message_of(when + "do = \"halt\"\n")
                .find("events.toml:3: top level.event[0] do: unknown value 'halt'"),
            std::string::npos);
  EXPECT_NE(message_of(when).find("'do' is required"), std::string::npos);
  EXPECT_NE(message_of(when + "do = { ramp_s = 1 }\n").find("'set' is required"),
            std::string::npos);
  EXPECT_NE(message_of(when + "do = { set = { vehicle_speed_mps = 1 } }\n")
                .find("an event sets inputs only"),
            std::string::npos);
  EXPECT_NE(
      message_of(when + "do = { set = { throttle_pedal = 1.5 } }\n").find("1.5 is outside [0, 1]"),
      std::string::npos);
  EXPECT_NE(message_of(when + "do = { set = { gear_request = 2.5 } }\n").find("not a whole number"),
            std::string::npos);
  EXPECT_NE(message_of(when + "do = { set = { throtle_pedal = 1 } }\n").find("throttle_pedal"),
            std::string::npos);  // the closest name
  EXPECT_NE(
      message_of(when + "do = { set = { throttle_pedal = 1 }, ramp_s = -1 }\n").find("ramp_s"),
      std::string::npos);
  EXPECT_NE(message_of(when + "do = { set = { throttle_pedal = 1, unit1.throttle_pedal = 0 } }\n")
                .find("is set twice"),
            std::string::npos);
  EXPECT_NE(
      message_of("[[event]]\nwhen = { signal = \"x\", op = \">\", value = 1 }\ndo = \"stop\"\n")
          .find("unknown signal 'x'"),
      std::string::npos);
  EXPECT_NE(
      message_of("[[event]]\nwhen = { signal = \"vehicle_speed_mps\", op = \"=>\", value = 1 }\n"
                 "do = \"stop\"\n")
          .find("unknown value '=>' (expected one of: <, <=, >, >=, ==, !=)"),
      std::string::npos);
  EXPECT_NE(
      message_of("[[event]]\nwhen = { signal = \"vehicle_speed_mps\", value = 1 }\ndo = \"stop\"\n")
          .find("'op' is required"),
      std::string::npos);
  EXPECT_NE(message_of("[[event]]\nwhen = { signal = \"vehicle_speed_mps\", op = \">\", value = 1, "
                       "for_s = -1 }\ndo = \"stop\"\n")
                .find("for_s: value -1 out of range"),
            std::string::npos);
  EXPECT_NE(
      message_of("[[event]]\nwhen = { signal = \"vehicle_speed_mps\", op = \">\", value = nan }\n"
                 "do = \"stop\"\n")
          .find("value: must be finite"),
      std::string::npos);
  EXPECT_NE(message_of(when + "do = \"stop\"\nat_s = 3\n").find("unknown key 'at_s'"),
            std::string::npos);
  const std::string named =
      "[[event]]\nname = \"a\"\nwhen = { signal = \"vehicle_speed_mps\", op = "
      "\">\", value = 1 }\ndo = \"stop\"\n";
  EXPECT_NE(message_of(named + named).find("duplicate event name 'a'"), std::string::npos);
}

TEST(ScenarioEvents, ComparisonsNeverHoldOnNan) {
  const double nan = std::nan("");
  EXPECT_TRUE(compare(CompareOp::kLess, 1, 2));
  EXPECT_FALSE(compare(CompareOp::kLess, 2, 2));
  EXPECT_TRUE(compare(CompareOp::kLessEqual, 2, 2));
  EXPECT_TRUE(compare(CompareOp::kGreater, 3, 2));
  EXPECT_TRUE(compare(CompareOp::kGreaterEqual, 2, 2));
  EXPECT_TRUE(compare(CompareOp::kEqual, 2, 2));
  EXPECT_TRUE(compare(CompareOp::kNotEqual, 1, 2));
  for (const auto op : {CompareOp::kLess, CompareOp::kLessEqual, CompareOp::kGreater,
                        CompareOp::kGreaterEqual, CompareOp::kEqual, CompareOp::kNotEqual})
    EXPECT_FALSE(compare(op, nan, 0.0)) << compare_op_name(op);
}

// The condition must hold for for_s without a break: x >= 1 from t = 0.1 to 0.3 (broken), and
// again from t = 0.5: with for_s = 0.25 it fires at t = 0.75 (h = 0.01 s).
TEST(ScenarioEvents, FiresAfterForSOfUnbrokenCondition) {
  EventStage stage(parse(R"(
[[event]]
when = { signal = "unit1.position_x_m", op = ">=", value = 1.0, for_s = 0.25 }
do = { set = { throttle_pedal = 0.5 } }
)"));
  View v;
  double fired_at = -1;
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.01 * k;
    v.x((t >= 0.1 - 1e-9 && t < 0.3) || t >= 0.5 - 1e-9 ? 1.0 : 0.0);
    v.update(stage, t);
    if (!stage.fired().empty()) fired_at = t;
  }
  EXPECT_NEAR(fired_at, 0.75, 1e-9);
  EXPECT_NEAR(stage.fired_at_s(0), 0.75, 1e-9);
  EXPECT_DOUBLE_EQ(v.s[Signal::kThrottlePedal], 0.5);
  EXPECT_TRUE(v.s.valid[model::index(Signal::kThrottlePedal)]);
}

// An invalid signal does not hold (the report flagged invalid after a fault).
TEST(ScenarioEvents, AnInvalidSignalDoesNotHold) {
  EventStage stage(parse(R"(
[[event]]
when = { signal = "unit1.position_x_m", op = ">=", value = 0.0 }
do = "stop"
)"));
  View v;
  v.r.valid = 0;
  EXPECT_FALSE(v.update(stage, 0.0));
  v.r.valid = 1;
  EXPECT_TRUE(v.update(stage, 0.01));
  EXPECT_FALSE(v.update(stage, 0.02));  // once
}

// The ramp starts at the input's value at the firing (the driver's 0.2) and reaches the target
// after ramp_s; a later event takes the input over from where the first left it; the driver's
// writes never show through.
TEST(ScenarioEvents, SetRampsAndHoldsOverTheDriver) {
  EventStage stage(parse(R"(
[[event]]
name = "a"
when = { signal = "unit1.position_x_m", op = ">", value = 1.0 }
do = { set = { throttle_pedal = 0.8 }, ramp_s = 0.1 }
[[event]]
name = "b"
when = { signal = "unit1.position_x_m", op = ">", value = 2.0 }
do = { set = { throttle_pedal = 0.0 } }
)"));
  View v;
  const auto throttle_at = [&](double t, double x) {
    v.s.set(Signal::kThrottlePedal, 0.2);  // the driver, every cycle
    v.x(x);
    v.update(stage, t);
    return v.s[Signal::kThrottlePedal];
  };
  EXPECT_DOUBLE_EQ(throttle_at(0.0, 0.0), 0.2);
  EXPECT_DOUBLE_EQ(throttle_at(1.0, 1.5), 0.2);  // fires: ramp from 0.2 at t = 1.0
  EXPECT_NEAR(throttle_at(1.05, 1.5), 0.5, 1e-12);
  EXPECT_NEAR(throttle_at(1.1, 1.5), 0.8, 1e-12);
  EXPECT_NEAR(throttle_at(5.0, 1.5), 0.8, 1e-12);  // held
  EXPECT_NEAR(throttle_at(6.0, 2.5), 0.0, 1e-12);  // b takes over: a step
  EXPECT_NEAR(stage.fired_at_s(0), 1.0, 1e-12);
  EXPECT_NEAR(stage.fired_at_s(1), 6.0, 1e-12);
}

TEST(ScenarioEvents, UpdateDoesNotAllocate) {
  EventStage stage(parse(R"(
[[event]]
when = { signal = "unit1.position_x_m", op = ">", value = 0.5, for_s = 0.1 }
do = { set = { throttle_pedal = 0.8, brake_pressure_front_pa = 1e6 }, ramp_s = 0.2 }
[[event]]
when = { signal = "throttle_pedal", op = ">=", value = 0.79 }
do = "stop"
)"));
  View v;
  const test::AllocationCounter allocations;
  for (int k = 0; k < 5000; ++k) {
    v.x(0.001 * k);
    v.update(stage, 0.001 * k);
  }
  EXPECT_EQ(allocations.count(), 0u);
  EXPECT_FALSE(std::isnan(stage.fired_at_s(1)));
}

// Through the executive (fake clock): the events run after the driver stage on the previous
// step's report, a set reaches the next step, `stop` ends the run after that cycle (reason
// "event"). The first cycle has no previous step: the model's outputs are not valid yet, so
// "x >= 0 for 5 ms" holds from the first step's x (t = 1 ms) and fires at t = 6 ms. The
// oscillator's trajectory is recomputed here by its own formula.
TEST(ScenarioEvents, ExecutiveFiresOnTheLastStepAndStops) {
  ExecutiveParams p;
  p.duration_s = 10.0;
  test::FakeClock clock;
  test::OscillatorModel model(p.period_s);
  EventLog log("");
  Executive exec(p, clock, model, nullptr, {}, {}, log, {});
  EventStage stage(parse(R"(
[[event]]
name = "push"
when = { signal = "unit1.position_x_m", op = ">=", value = 0.0, for_s = 0.005 }
do = { set = { throttle_pedal = 1.0 }, ramp_s = 0.01 }
[[event]]
name = "end"
when = { signal = "unit1.position_x_m", op = ">", value = 1e-4 }
do = "stop"
)"));
  exec.set_events(&stage);
  EXPECT_EQ(exec.run_loop(), StopReason::kEvent);
  EXPECT_STREQ(stop_reason_name(StopReason::kEvent), "event");
  // the oscillator (tests/rig/test_model.h): v += h (u - 4 x - 0.4 v), x += h v; u from the
  // ramp of the step's time t = k h
  const double h = p.period_s;
  double x = 0, v = 0;
  std::uint64_t k = 0;
  for (; x <= 1e-4; ++k) {
    const double t = static_cast<double>(k) * h;
    const double u = t < 0.006 - 1e-12 ? 0.0 : std::min(1.0, (t - 0.006) / 0.01);
    v += h * (u - 4 * x - 0.4 * v);
    x += h * v;
  }
  // the condition is seen at the driver stage of cycle k (on step k's result), which still steps
  EXPECT_EQ(exec.cycles(), k + 1);
  EXPECT_NEAR(stage.fired_at_s(0), 0.006, 1e-12);
  EXPECT_NEAR(stage.fired_at_s(1), static_cast<double>(k) * h, 1e-12);
}

}  // namespace
}  // namespace rig::driver
