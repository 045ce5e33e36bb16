/// rig/routing: which source feeds each input, decided once, and the sets handed to the CAN
/// bridge, the driver and the model.

#include "rig/routing.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/config/config_error.h"
#include "rig/config.h"
#include "rig/driver/path_driver.h"
#include "rig/model_factory.h"

namespace rig {
namespace {

using model::Signal;
using model::SignalSource;

constexpr std::size_t idx(Signal s) { return model::index(s); }

io::InputSet set_of(std::initializer_list<Signal> signals) {
  io::InputSet out;
  for (const Signal s : signals) out.set(idx(s));
  return out;
}

RigConfig load_text(const std::string& name, const std::string& text) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("rig_routing_test_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(file) << text;
  RigConfig c = load_config(file);
  std::filesystem::remove(file);
  return c;
}

TEST(Routing, CanWinsOverTheDriverAndTheRestIsTheModels) {
  RoutingRequests requests{};
  requests[idx(Signal::kThrottlePedal)] = RouteRequest::kCan;
  requests[idx(Signal::kAssistTorque)] = RouteRequest::kDriver;  // named, no driver writes it
  const Routing r = resolve_routing(requests, driver::path_driver_inputs());
  EXPECT_EQ(r.source[idx(Signal::kThrottlePedal)], SignalSource::kCan);
  EXPECT_EQ(r.source[idx(Signal::kSteeringWheelAngleCmd)], SignalSource::kDriver);
  EXPECT_EQ(r.source[idx(Signal::kBrakePressureFront)], SignalSource::kDriver);
  EXPECT_EQ(r.source[idx(Signal::kBrakePressureRear)], SignalSource::kDriver);
  EXPECT_EQ(r.source[idx(Signal::kGearRequest)], SignalSource::kDriver);
  EXPECT_EQ(r.source[idx(Signal::kAssistTorque)], SignalSource::kDriver);
  EXPECT_EQ(r.source[idx(Signal::kSteeringWheelTorqueCmd)], SignalSource::kModel);
  EXPECT_EQ(r.source[idx(Signal::kVehicleSpeed)], SignalSource::kModel);  // outputs
  EXPECT_EQ(r.can_inputs, set_of({Signal::kThrottlePedal}));
  EXPECT_EQ(r.driver_inputs,
            set_of({Signal::kSteeringWheelAngleCmd, Signal::kBrakePressureFront,
                    Signal::kBrakePressureRear, Signal::kGearRequest, Signal::kAssistTorque}));
  EXPECT_FALSE(r.assist_from_input);  // "driver": the built-in boost curve
}

TEST(Routing, AssistFromCanIsTheEcusTorque) {
  RoutingRequests requests{};
  requests[idx(Signal::kAssistTorque)] = RouteRequest::kCan;
  const Routing r = resolve_routing(requests, {});
  EXPECT_TRUE(r.assist_from_input);
  EXPECT_EQ(r.can_inputs, set_of({Signal::kAssistTorque}));
  EXPECT_TRUE(r.driver_inputs.none());
  EXPECT_FALSE(resolve_routing({}, {}).assist_from_input);  // unrouted: the boost curve
}

// A driver that writes the assist (a table column) plays the ECU: its torque, not the boost curve
// (parking effort with the assist off and the ignition on); a routed steering angle lets the
// robot go while it is not valid.
TEST(Routing, DriverWrittenAssistIsTheInputAndAngleHasASource) {
  RoutingRequests requests{};
  requests[idx(Signal::kAssistTorque)] = RouteRequest::kDriver;
  const Routing r = resolve_routing(requests, set_of({Signal::kAssistTorque}));
  EXPECT_TRUE(r.assist_from_input);
  EXPECT_FALSE(r.angle_from_input);  // nobody feeds the angle: the robot holds 0
  EXPECT_TRUE(resolve_routing({}, set_of({Signal::kSteeringWheelAngleCmd})).angle_from_input);
  RoutingRequests angle_can{};
  angle_can[idx(Signal::kSteeringWheelAngleCmd)] = RouteRequest::kCan;
  EXPECT_TRUE(resolve_routing(angle_can, {}).angle_from_input);
}

TEST(Routing, ResolvedOnceFromTheConfigurationFile) {
  const RigConfig c =
      load_text("path.toml",
                "[routing]\nassist_torque_nm = \"can\"\n"
                "brake_pressure_rear_pa = \"can\"\n"
                "[driver]\nkind = \"path\"\n"
                "[can]\nmapping = \"" RIG_SOURCE_DIR "/config/can/steering-bench.toml\"\n");
  EXPECT_TRUE(c.routing.assist_from_input);
  EXPECT_EQ(c.routing.can_inputs, set_of({Signal::kAssistTorque, Signal::kBrakePressureRear}));
  EXPECT_EQ(c.routing.driver_inputs, set_of({Signal::kSteeringWheelAngleCmd, Signal::kThrottlePedal,
                                             Signal::kBrakePressureFront, Signal::kGearRequest}));
  // The path driver writes what it feeds and leaves the CAN-routed rear circuit alone.
  auto d = make_driver(c);
  ASSERT_NE(d, nullptr);
  model::Signals s;
  s.set(Signal::kBrakePressureRear, -3.0);
  s.set(Signal::kVehicleSpeed, 30.0);  // far above the target: the speed controller brakes
  d->update(1.0, s);
  EXPECT_GT(s[Signal::kBrakePressureFront], 0.0);
  EXPECT_DOUBLE_EQ(s[Signal::kBrakePressureRear], -3.0);
  EXPECT_DOUBLE_EQ(s[Signal::kGearRequest], 99.0);
}

// Without a [can] section nothing writes an input routed to CAN (issue 13: the front brakes
// were never applied): an error at its [routing] line.
TEST(Routing, CanRouteNeedsACanSection) {
  try {
    (void)load_text("no_can.toml", "[routing]\n\nbrake_pressure_front_pa = \"can\"\n");
    ADD_FAILURE() << "no error";
  } catch (const io::config::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(":3: [routing] brake_pressure_front_pa: routed to \"can\", but there is "
                        "no [can] section"),
              std::string::npos)
        << what;
  }
  const RigConfig c =
      load_text("with_can.toml",
                "[routing]\n\nbrake_pressure_front_pa = \"can\"\n"
                "[can]\nmapping = \"" RIG_SOURCE_DIR "/config/can/steering-bench.toml\"\n");
  EXPECT_NE(c.can_route_at[idx(Signal::kBrakePressureFront)].at.find("with_can.toml:3"),
            std::string::npos);
  EXPECT_TRUE(c.can_route_at[idx(Signal::kThrottlePedal)].at.empty());
}

TEST(Routing, TableColumnsAreTheDriversAndMustNotBeRoutedToCan) {
  const RigConfig c = load_text("table.toml",
                                "[driver]\ncolumns = [\"time_s\", \"throttle_pedal\"]\n"
                                "rows = [[0, 0.5]]\n");
  EXPECT_EQ(c.routing.driver_inputs, set_of({Signal::kThrottlePedal}));
  EXPECT_EQ(c.routing.source[idx(Signal::kThrottlePedal)], SignalSource::kDriver);
  EXPECT_TRUE(c.routing.can_inputs.none());
  try {
    (void)load_text("clash.toml",
                    "[routing]\nthrottle_pedal = \"can\"\n"
                    "[driver]\ncolumns = [\"time_s\", \"throttle_pedal\"]\nrows = [[0, 0.5]]\n");
    ADD_FAILURE() << "no error";
  } catch (const io::config::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(":4: "), std::string::npos) << what;  // the columns line
    EXPECT_NE(what.find("'throttle_pedal' is routed to CAN in [routing]"), std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace rig
