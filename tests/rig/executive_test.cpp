/// Executive, statistics, event log, table driver and configuration tests (fake clock, no
/// sleeping).

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <string>

#include "io/config/config_error.h"
#include "rig/config.h"
#include "rig/driver/table_driver.h"
#include "rig/event_log.h"
#include "rig/executive.h"
#include "rig/model_factory.h"
#include "rig/summary.h"
#include "tests/rig/fake_clock.h"
#include "tests/rig/test_model.h"
#include "tests/support/alloc_counter.h"

namespace rig {
namespace {

using model::Signal;
using test::FakeClock;

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("rig_exec_test_" + std::to_string(::getpid()) + "_" + name);
}

struct Harness {
  explicit Harness(ExecutiveParams p, std::string log_path = "")
      : model(p.period_s), log(log_path), exec(p, clock, model, nullptr, {}, {}, log, routing()) {}
  static Executive::Sources routing() { return {}; }
  FakeClock clock;
  test::OscillatorModel model;
  EventLog log;
  Executive exec;
};

// ---- Executive with a fake clock ----
TEST(Executive, CountsCyclesAndStatisticsWithoutMisses) {
  ExecutiveParams p;
  p.duration_s = 0.1;
  Harness hx(p);
  hx.model.on_step = [&](std::uint64_t) { hx.clock.advance(200'000); };  // 0.2 ms compute
  EXPECT_EQ(hx.exec.run_loop(), StopReason::kDuration);
  EXPECT_EQ(hx.exec.cycles(), 100u);
  EXPECT_EQ(hx.exec.deadline_misses(), 0u);
  EXPECT_EQ(hx.exec.lateness().max(), 0);
  EXPECT_EQ(hx.exec.compute().max(), 200'000);
  EXPECT_EQ(hx.exec.phase(io::Phase::kModel).max(), 200'000);
  EXPECT_DOUBLE_EQ(hx.exec.sim_time_s(), 0.1);
  // Drift = sim - loop clock: the last cycle (deadline +100 ms) ends 0.2 ms after its deadline.
  EXPECT_NEAR(hx.exec.sim_time_s() - hx.exec.loop_time_s(), -0.0002, 1e-12);
  EXPECT_EQ(hx.exec.drain_snapshots(), 100u);
}

TEST(Executive, LatenessIsWakeMinusDeadline) {
  ExecutiveParams p;
  p.duration_s = 0.01;
  Harness hx(p);
  hx.model.on_step = [&](std::uint64_t n) {
    if (n == 3) hx.clock.next_wake_lateness_ns = 70'000;  // the next cycle wakes 70 us late
  };
  hx.exec.run_loop();
  EXPECT_EQ(hx.exec.cycles(), 10u);
  EXPECT_EQ(hx.exec.lateness().max(), 70'000);
  EXPECT_EQ(hx.exec.lateness().quantile(0.5), 0);
  EXPECT_EQ(hx.exec.deadline_misses(), 0u);
}

TEST(Executive, SkipDropsMissedPeriodsAndStaysPhaseAligned) {
  ExecutiveParams p;
  p.duration_s = 0.1;
  p.policy = OverrunPolicy::kSkip;
  const auto log_path = temp_path("skip.jsonl");
  {
    Harness hx(p, log_path.string());
    // Cycle 10's step takes 3.5 ms: its work ends 3.5 ms after its deadline -> miss; the next
    // deadlines at +1, +2, +3 ms have passed, so 3 periods are skipped and cycle 11 aims at +4 ms.
    hx.model.on_step = [&](std::uint64_t n) { hx.clock.advance(n == 10 ? 3'500'000 : 100'000); };
    EXPECT_EQ(hx.exec.run_loop(), StopReason::kDuration);
    EXPECT_EQ(hx.exec.deadline_misses(), 1u);
    EXPECT_EQ(hx.exec.skipped_periods(), 3u);
    EXPECT_EQ(hx.exec.cycles(), 97u);        // 100 deadlines, 3 skipped
    EXPECT_EQ(hx.exec.lateness().max(), 0);  // phase-aligned: nobody wakes late
    // Drift: 3 periods lost, and the last cycle ends 0.1 ms after its deadline.
    EXPECT_NEAR(hx.exec.sim_time_s() - hx.exec.loop_time_s(), -0.003 - 0.0001, 1e-12);
    hx.log.stop();
  }
  const std::string log = read_file(log_path);
  EXPECT_NE(log.find("\"cycle\":10,"), std::string::npos) << log;
  EXPECT_NE(log.find("\"action\":\"skip:3\""), std::string::npos) << log;
  EXPECT_NE(log.find("\"model\":3500000"), std::string::npos) << log;
  EXPECT_NE(log.find("\"consecutive_misses\":1"), std::string::npos) << log;
  std::filesystem::remove(log_path);
}

TEST(Executive, CatchUpRunsMissedStepsBackToBack) {
  ExecutiveParams p;
  p.duration_s = 0.1;
  p.policy = OverrunPolicy::kCatchUp;
  Harness hx(p);
  hx.model.on_step = [&](std::uint64_t n) { hx.clock.advance(n == 10 ? 3'500'000 : 100'000); };
  hx.exec.run_loop();
  EXPECT_EQ(hx.exec.cycles(), 100u);  // every step is run: simulated time tracks wall time
  EXPECT_EQ(hx.exec.skipped_periods(), 0u);
  // Cycle 10 ends at +3.5 ms; cycle 11 (deadline +1 ms) wakes 2.5 ms late, 12 at 1.6 ms, 13 at
  // 0.7 ms; cycles 11 and 12 end after their next deadline too -> 3 misses in a row.
  EXPECT_EQ(hx.exec.lateness().max(), 2'500'000);
  EXPECT_EQ(hx.exec.deadline_misses(), 3u);
  EXPECT_DOUBLE_EQ(hx.exec.sim_time_s(), 0.1);
}

TEST(Executive, AbortAfterNConsecutiveMisses) {
  ExecutiveParams p;
  p.duration_s = 1.0;
  p.policy = OverrunPolicy::kAbortAfter;
  p.abort_after = 3;
  Harness hx(p);
  // From step 20 on, every step takes 1.5 ms: each cycle misses.
  hx.model.on_step = [&](std::uint64_t n) { hx.clock.advance(n >= 20 ? 1'500'000 : 100'000); };
  EXPECT_EQ(hx.exec.run_loop(), StopReason::kAbortAfter);
  EXPECT_EQ(hx.exec.cycles(), 23u);
  EXPECT_EQ(hx.exec.deadline_misses(), 3u);
}

/// A sink that keeps what the fault tests look at: validity and the first unit's x per snapshot.
class ValiditySink final : public io::SnapshotSink {
 public:
  void start(const io::RunInfo&) override {}
  void consume(const io::Snapshot& s, std::uint64_t) override {
    valid.push_back(s.report.valid);
    kind.push_back(s.report.fault_kind);
    x.push_back(s.report.units[0].position_m[0]);
    speed_valid.push_back(s.signals.valid[model::index(Signal::kVehicleSpeed)]);
  }
  void stop() override {}
  std::vector<int> valid, kind;
  std::vector<double> x;
  std::vector<bool> speed_valid;
};

TEST(Executive, VehicleFaultStopsWithItsEvent) {
  ExecutiveParams p;
  p.duration_s = 1.0;
  p.unit_files = {"tractor.toml", "trailer.toml"};
  const auto log_path = temp_path("fault.jsonl");
  {
    Harness hx(p, log_path.string());
    hx.model.fault_at_step = 42;
    EXPECT_EQ(hx.exec.run_loop(), StopReason::kVehicleFault);
    EXPECT_EQ(hx.exec.cycles(), 43u);
    EXPECT_EQ(hx.exec.vehicle_fault().kind, model::FaultKind::kRoll);
    EXPECT_EQ(hx.exec.vehicle_fault().unit, 1);
    EXPECT_EQ(hx.exec.fault_unit_file(), "trailer.toml");
    EXPECT_FALSE(hx.exec.signals().valid[model::index(Signal::kVehicleSpeed)]);
    hx.log.stop();
  }
  const std::string log = read_file(log_path);
  EXPECT_NE(log.find("\"event\":\"vehicle_fault\""), std::string::npos) << log;
  EXPECT_NE(log.find("vehicle fault roll: roll 1.25 rad beyond the limit 1 rad at t = 0.043000 s, "
                     "unit 1 (trailer.toml); stopping"),
            std::string::npos)
      << log;
  std::filesystem::remove(log_path);
}

TEST(Executive, HeldVehicleFaultFreezesTheModelAndTheLoopRunsOn) {
  ExecutiveParams p;
  p.duration_s = 0.1;
  p.hold_on_vehicle_fault = true;
  test::OscillatorModel model(p.period_s);
  FakeClock clock;
  EventLog log("");
  ValiditySink sink;
  Executive exec(p, clock, model, nullptr, {}, {&sink}, log, Harness::routing());
  model.fault_at_step = 30;
  EXPECT_EQ(exec.run_loop(), StopReason::kDuration);
  exec.drain_snapshots();
  EXPECT_EQ(exec.cycles(), 100u);
  EXPECT_EQ(model.steps(), 30u);  // frozen at its last fault-free state: never stepped again
  EXPECT_EQ(exec.vehicle_fault().kind, model::FaultKind::kRoll);
  ASSERT_EQ(sink.valid.size(), 100u);
  for (std::size_t k = 0; k < 100; ++k) {
    EXPECT_EQ(sink.valid[k], k < 30 ? 1 : 0) << k;
    EXPECT_EQ(sink.kind[k], k < 30 ? 0 : static_cast<int>(model::FaultKind::kRoll)) << k;
    EXPECT_EQ(sink.speed_valid[k], k < 30) << k;
    if (k >= 30) {
      EXPECT_EQ(sink.x[k], sink.x[29]) << k;  // frozen
    }
  }
}

TEST(Executive, StopsCleanlyOnNonFiniteModel) {
  ExecutiveParams p;
  p.duration_s = 1.0;
  const auto log_path = temp_path("nan.jsonl");
  {
    Harness hx(p, log_path.string());
    hx.model.nan_at_step = 42;
    EXPECT_EQ(hx.exec.run_loop(), StopReason::kNonFinite);
    EXPECT_EQ(hx.exec.cycles(), 43u);
    hx.log.stop();
  }
  EXPECT_NE(read_file(log_path).find("\"event\":\"non_finite\""), std::string::npos);
  std::filesystem::remove(log_path);
}

// After a NaN stop the summary is still strict JSON: every non-finite number is null.
TEST(Summary, NonFiniteNumbersAreNull) {
  ExecutiveParams p;
  p.duration_s = 1.0;
  Harness hx(p);
  hx.model.nan_at_step = 42;
  EXPECT_EQ(hx.exec.run_loop(), StopReason::kNonFinite);
  SummaryExtras extras;
  extras.wall_time_s = std::numeric_limits<double>::quiet_NaN();
  extras.write_failures.push_back({3, "LCM log \"x\".lcm: No space left on device"});
  const std::string json = summary_json(hx.exec, extras);
  EXPECT_NE(json.find("\"vehicle_speed_mps\": null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"wall_time_s\": null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"write_failures\": [{\"output\": \"LCM log \\\"x\\\".lcm: No space left "
                      "on device\", \"count\": 3}]"),
            std::string::npos)
      << json;
  EXPECT_EQ(json.find("inf"), std::string::npos) << json;
  EXPECT_EQ(json.find("nan"), std::string::npos) << json;
}

TEST(Executive, RequestStopEndsTheLoop) {
  ExecutiveParams p;  // duration 0: forever
  Harness hx(p);
  hx.model.on_step = [&](std::uint64_t n) {
    if (n == 7) hx.exec.request_stop();
  };
  EXPECT_EQ(hx.exec.run_loop(), StopReason::kRequested);
  EXPECT_EQ(hx.exec.cycles(), 8u);
}

TEST(EventLog, OverflowWritesTheLostCount) {
  const auto log_path = temp_path("overflow.jsonl");
  {
    EventLog log(log_path.string(), 8);
    for (int i = 0; i < 20; ++i) log.event(0, i, "e", "x");  // not drained: 12 lost
    EXPECT_EQ(log.lost(), 12u);
    log.stop();
  }
  const std::string text = read_file(log_path);
  EXPECT_NE(text.find("{\"event\":\"ring_overflow\",\"lost\":12}"), std::string::npos) << text;
  std::filesystem::remove(log_path);
}

// ---- Table driver ----
TEST(TableDriver, InterpolatesLinearlyAndHoldsEnds) {
  driver::TableDriverParams p;
  p.columns = {model::index(Signal::kThrottlePedal), model::index(Signal::kBrakePressureFront)};
  p.times_s = {1.0, 2.0, 4.0};
  p.values = {0.0, 0.0, 1.0, 10.0, 0.5, 30.0};
  io::InputSet feeds;  // the routing sends the brake pressure from CAN: not the table's
  feeds.set(model::index(Signal::kThrottlePedal));
  driver::TableDriver d(p, feeds);
  model::Signals s;
  s[Signal::kBrakePressureFront] = -7.0;
  d.update(0.0, s);
  EXPECT_DOUBLE_EQ(s[Signal::kThrottlePedal], 0.0);
  d.update(1.5, s);
  EXPECT_DOUBLE_EQ(s[Signal::kThrottlePedal], 0.5);
  d.update(3.0, s);
  EXPECT_DOUBLE_EQ(s[Signal::kThrottlePedal], 0.75);
  d.update(9.0, s);
  EXPECT_DOUBLE_EQ(s[Signal::kThrottlePedal], 0.5);
  EXPECT_DOUBLE_EQ(s[Signal::kBrakePressureFront], -7.0);  // CAN-routed input untouched
}

// A nan cell: the input is not given (invalid) between the rows next to it (returnability: the
// steering robot lets go), given again from the next number on.
TEST(TableDriver, NanCellIsNotGivenBetweenItsNeighbours) {
  driver::TableDriverParams p;
  p.columns = {model::index(Signal::kSteeringWheelAngleCmd)};
  p.times_s = {0.0, 1.0, 1.001, 3.0, 3.5};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  p.values = {0.0, 1.5, nan, nan, 0.2};
  driver::TableDriver d(p);
  model::Signals s;
  const std::size_t slot = model::index(Signal::kSteeringWheelAngleCmd);
  d.update(0.5, s);
  EXPECT_TRUE(s.valid[slot]);
  EXPECT_DOUBLE_EQ(s[Signal::kSteeringWheelAngleCmd], 0.75);
  d.update(1.0, s);
  EXPECT_TRUE(s.valid[slot]);
  EXPECT_DOUBLE_EQ(s[Signal::kSteeringWheelAngleCmd], 1.5);
  for (const double t : {1.0005, 2.0, 3.0, 3.25}) {
    d.update(t, s);
    EXPECT_FALSE(s.valid[slot]) << t;
  }
  d.update(3.5, s);
  EXPECT_TRUE(s.valid[slot]);
  EXPECT_DOUBLE_EQ(s[Signal::kSteeringWheelAngleCmd], 0.2);
}

// ---- Configuration ----
struct ConfigCase {
  std::string text;
  std::string message;  // expected in the error after "file:line: "
  int line;
};

TEST(Config, BadInputGivesFileLine) {
  const std::vector<ConfigCase> cases = {
      {"[rig]\nperiod_s = 0.001\nbogus = 1\n", "unknown key 'bogus'", 3},
      {"[rig]\n\nperiod_s = 0.0\n", "must be > 0", 3},
      {"[rig]\nperiod_s = 2.0\n", "must be > 0", 2},
      // issue 13: a period that rounds to 0 ns divided by zero; the loop counts whole ns
      {"[rig]\nperiod_s = 1e-10\n", "value 1e-10 out of range: must be > 0, within [1e-05, 1] s",
       2},
      {"[rig]\nstep_s = 0.0010000005\n", "0.0010000005 s is not a whole number of nanoseconds", 2},
      {"[rig]\nperiod_s = 0.001\nduration_s = 0.0004\n",
       "0.0004 s is shorter than one period (0.001 s); 0 runs until stopped", 3},
      {"[rig]\nduration_s = nan\n", "value nan out of range", 2},
      {"[rig]\nkeep_logs = 1001\n", "keep_logs: must be an integer in [0, 1000]", 2},
      {"[rig]\noverrun_policy = \"sometimes\"\n", "unknown value 'sometimes'", 2},
      {"[rig]\n[rigg]\nx = 1\n", "unknown key 'rigg'", 2},
      {"[routing]\nthrottle_pedal = \"ecu\"\n", "unknown value 'ecu'", 2},
      {"[routing]\nvehicle_speed_mps = \"driver\"\n", "is an output", 2},
      {"[driver]\ncolumns = [\"time_s\", \"throttle\"]\nrows = [[0, 1]]\n",
       "unknown signal 'throttle'", 2},
      {"[driver]\ncolumns = [\"time_s\", \"throttle_pedal\"]\nrows = [[1, 1], [0, 1]]\n",
       "increase", 3},
      {"[model]\nkind = \"bus\"\n", "unknown value 'bus'", 2},
      {"[driver]\nkind = \"path\"\npath = \"slalom\"\n", "unknown value 'slalom'", 3},
      {"[driver]\nkind = \"path\"\ntarget_speed = 10\n", "unknown key 'target_speed'", 3},
      {"[driver]\nkind = \"path\"\n\nstop_time_s = -1\n", "stop_time_s", 4},
      {"[rig]\nfault_roll_limit_rad = -1.0\n", "fault_roll_limit_rad: must be finite and > 0", 2},
      {"[rig]\n\nfault_pitch_limit_rad = 0\n", "fault_pitch_limit_rad: must be", 3},
      {"[rig]\nfault_speed_limit_mps = -100\n", "fault_speed_limit_mps: must be", 2},
      {"[rig]\nfault_rate_limit_radps = nan\n", "fault_rate_limit_radps: must be", 2},
      {"[rig]\non_vehicle_fault = \"ignore\"\n", "unknown value 'ignore'", 2},
      // issue 13: integer keys take integers; a CPU this machine has; driver tables finite and
      // within the input's range, at the row's line
      {"[rig]\npriority = 80.7\n", "[rig] priority: expected an integer, not 80.7", 2},
      {"[rig]\n\nabort_after = 3.0\n", "[rig] abort_after: expected an integer", 3},
      {"[rig]\ncpu = 100000\n", "out of range", 2},
      {"[rig]\ncpu = 1023\n", "CPU 1023 does not exist: this machine has", 2},
      // (a nan cell is "not given", rig/driver/table_driver.h; an infinity is an error)
      {"[driver]\ncolumns = [\"time_s\", \"throttle_pedal\"]\nrows = [\n[0, 0.5],\n[1, inf]]\n",
       "[driver] rows: throttle_pedal: value is not finite", 5},
      {"[driver]\ncolumns = [\"time_s\", \"throttle_pedal\"]\nrows = [[0, 1.01]]\n",
       "throttle_pedal: 1.01 is outside [0, 1]", 3},
      {"[driver]\ncolumns = [\"time_s\", \"gear_request\"]\nrows = [\n[0, 1],\n[1, 1.5]]\n",
       "gear_request: 1.5 is outside [-1, 99] or not a whole number", 5},
      {"[driver]\ncolumns = [\"time_s\", \"brake_pressure_rear_pa\"]\nrows = [[-inf, 0]]\n",
       "time_s: value is not finite", 3},
      {"[lcm]\nurl = \"udpm://239.255.76.67:7667?ttl=x\"\n", "[lcm] url: ttl 'x' is not in 0..255",
       2},
  };
  for (const auto& c : cases) {
    const auto file = temp_path("bad.toml");
    std::ofstream(file) << c.text;
    try {
      (void)load_config(file);
      ADD_FAILURE() << "no error for:\n" << c.text;
    } catch (const io::config::ConfigError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file.string() + ":" + std::to_string(c.line) + ":", 0), 0u) << what;
      EXPECT_NE(what.find(c.message), std::string::npos) << what;
    }
    std::filesystem::remove(file);
  }
  EXPECT_THROW((void)load_config("/nonexistent/rig.toml"), io::config::ConfigError);
}

TEST(Config, PaperQuarterCarConfigReproducesThePaperManeuver) {
  const RigConfig c = load_config(std::filesystem::path(RIG_SOURCE_DIR) /
                                  "config/maneuvers/paper-quarter-car.toml");
  EXPECT_DOUBLE_EQ(c.rig.period_s, 0.001);
  EXPECT_DOUBLE_EQ(c.model.quarter_car.grade, 0.10);
  ASSERT_TRUE(c.driver.has_value());
  driver::TableDriver d(*c.driver, c.routing.driver_inputs);
  model::Signals s;
  const auto torque = [&](double t) {
    d.update(t, s);
    return s[Signal::kThrottlePedal] * c.model.quarter_car.max_drive_torque_nm;
  };
  const auto brake = [&](double t) {
    d.update(t, s);
    return s[Signal::kBrakePressureFront] * c.model.quarter_car.brake_gain_nm_per_pa;
  };
  EXPECT_DOUBLE_EQ(torque(0.0), 1000.0);
  EXPECT_DOUBLE_EQ(torque(5.999), 1000.0);
  EXPECT_DOUBLE_EQ(torque(6.0), 0.0);
  EXPECT_DOUBLE_EQ(brake(8.0), 0.0);
  EXPECT_NEAR(brake(8.25), 750.0, 1e-9);
  EXPECT_NEAR(brake(8.5), 1500.0, 1e-9);
  EXPECT_NEAR(brake(17.999), 1500.0, 1e-9);
  EXPECT_DOUBLE_EQ(brake(18.0), 0.0);
}

TEST(Config, DefaultConfigIsTheSedanDemoWithThePathDriver) {
  const RigConfig c = load_config(std::filesystem::path(RIG_SOURCE_DIR) / "config/rig.toml");
  EXPECT_DOUBLE_EQ(c.rig.period_s, 0.001);
  ASSERT_EQ(c.model.kind, "vehicle");
  ASSERT_TRUE(c.model.vehicle.has_value());
  EXPECT_EQ(c.model.vehicle->params.axles.size(), 2u);
  // the road (issue 16): config/roads/demo-hill.xodr, a surface; gravity straight down
  EXPECT_DOUBLE_EQ(c.model.vehicle->params.road.grade, 0.0);
  EXPECT_TRUE(c.model.vehicle->params.road.surface != nullptr);
  ASSERT_TRUE(c.path_driver.has_value());
  EXPECT_FALSE(c.driver.has_value());
  // pure-pursuit geometry from the sedan: wheelbase 1.20 + 1.60 m, ratio 0.13 m / 0.008125 m/rad
  EXPECT_NEAR(c.path_driver->wheelbase_m, 2.80, 1e-12);
  EXPECT_NEAR(c.path_driver->steering_ratio, 16.0, 1e-9);
  for (const Signal s : {Signal::kSteeringWheelAngleCmd, Signal::kThrottlePedal,
                         Signal::kBrakePressureFront, Signal::kBrakePressureRear})
    EXPECT_EQ(c.routing.source[model::index(s)], model::SignalSource::kDriver)
        << model::info(s).name;
  // the stop phase on the hill: no throttle, 40/20 bar ramped over 0.5 s from 12 s and held
  auto d = make_driver(c);
  ASSERT_NE(d, nullptr);
  model::Signals s;
  s.set(Signal::kVehicleSpeed, 10.0);  // below the target: the speed controller pushes
  d->update(1.0, s);
  EXPECT_GT(s[Signal::kThrottlePedal], 0.5);
  EXPECT_DOUBLE_EQ(s[Signal::kBrakePressureFront], 0.0);
  d->update(12.25, s);
  EXPECT_DOUBLE_EQ(s[Signal::kThrottlePedal], 0.0);
  EXPECT_NEAR(s[Signal::kBrakePressureFront], 2.0e6, 1e-6);
  EXPECT_NEAR(s[Signal::kBrakePressureRear], 1.0e6, 1e-6);
  d->update(19.0, s);
  EXPECT_DOUBLE_EQ(s[Signal::kBrakePressureFront], 4.0e6);
}

// ---- Zero allocation on the loop thread ----
class AllocationProbe final : public CycleHook {
 public:
  void on_cycle(std::uint64_t cycle) noexcept override {
    if (cycle == 100) at_100 = test::thread_allocation_count();
    last = test::thread_allocation_count();
    last_cycle = cycle;
  }
  std::uint64_t at_100 = 0, last = 0, last_cycle = 0;
};

/// A sink that copies a value out of each snapshot (so the dispatcher really runs).
class CountingSink final : public io::SnapshotSink {
 public:
  void start(const io::RunInfo&) override {}
  void consume(const io::Snapshot& s, std::uint64_t dropped) override {
    ++count;
    lost += dropped;
    last_x = s.signals[Signal::kPositionX];
  }
  void stop() override { stopped = true; }
  std::uint64_t count = 0, lost = 0;
  double last_x = 0;
  bool stopped = false;
};

TEST(Executive, LoopThreadDoesNotAllocate) {
  const RigConfig config = load_config(std::filesystem::path(RIG_SOURCE_DIR) / "config/rig.toml");
  auto model = make_model(config);  // the sedan demo: vehicle model + path driver
  auto driver = make_driver(config);
  ASSERT_NE(driver, nullptr);
  rt::VirtualClock clock;
  EventLog log("");
  CountingSink sink;
  ExecutiveParams p;
  p.offline = true;  // the same loop, no SCHED_FIFO needed in the test
  p.duration_s = 12.0;
  p.policy = OverrunPolicy::kSkip;
  Executive exec(p, clock, *model, driver.get(), {}, {&sink}, log, config.routing.source);
  AllocationProbe probe;
  exec.set_hook(&probe);
  exec.prepare("config/rig.toml");
  exec.go();
  EXPECT_EQ(exec.join(), StopReason::kDuration);
  log.stop();
  EXPECT_EQ(probe.last_cycle, 12'000u);
  EXPECT_EQ(probe.last - probe.at_100, 0u) << "allocations on the loop thread over 11,900 cycles";
  EXPECT_EQ(sink.count, 12'000u);  // offline: back-pressure, nothing dropped
  EXPECT_EQ(sink.lost, 0u);
  EXPECT_TRUE(sink.stopped);
  EXPECT_DOUBLE_EQ(sink.last_x, exec.signals()[Signal::kPositionX]);
}

}  // namespace
}  // namespace rig
