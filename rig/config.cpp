#include "rig/config.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

#include "io/config/config_error.h"
#include "io/config/road_config.h"
#include "io/config/strict_table.h"
#include "model/vehicle/differential/differential_tree.h"
#include "rig/rt/thread_setup.h"

namespace rig {
namespace {

/// A limit that must be finite and > 0.
double positive(io::config::StrictTable& t, std::string_view key, double fallback) {
  const double v = t.number(key, fallback);
  if (!(v > 0) || !std::isfinite(v)) throw t.error(key, "must be finite and > 0");
  return v;
}

/// The vehicle-fault keys of [rig] (model/vehicle/vehicle_faults.h).
void read_vehicle_faults(io::config::StrictTable& t, RigSettings& s) {
  auto& l = s.fault_limits;
  l.roll_rad = positive(t, "fault_roll_limit_rad", l.roll_rad);
  l.pitch_rad = positive(t, "fault_pitch_limit_rad", l.pitch_rad);
  l.speed_mps = positive(t, "fault_speed_limit_mps", l.speed_mps);
  l.rate_radps = positive(t, "fault_rate_limit_radps", l.rate_radps);
  s.hold_on_vehicle_fault = t.choice("on_vehicle_fault", "stop", {"stop", "hold"}) == "hold";
}

/// period_s / step_s: the loop counts in whole nanoseconds, so a period must be one (else it
/// rounds: to 0 ns below 0.5 ns, and the first miss divides by it) and within [1e-5, 1] s.
double read_period(io::config::StrictTable& t, const char* key) {
  const double v = t.number(key);
  char text[160];
  if (!(v >= kMinPeriod_s && v <= kMaxPeriod_s)) {
    std::snprintf(text, sizeof text, "value %g out of range: must be > 0, within [%g, %g] s", v,
                  kMinPeriod_s, kMaxPeriod_s);
    throw t.error(key, text);
  }
  const double ns = v * 1e9;
  if (std::abs(ns - std::round(ns)) > 1e-3) {
    std::snprintf(text, sizeof text, "%.12g s is not a whole number of nanoseconds", v);
    throw t.error(key, text);
  }
  return v;
}

RigSettings read_rig(io::config::StrictTable& t) {
  RigSettings s;
  if (t.has("period_s") && t.has("step_s"))
    throw t.error("step_s", "give period_s or step_s, not both");
  const char* period_key = t.has("step_s") ? "step_s" : "period_s";
  if (t.has(period_key)) s.period_s = read_period(t, period_key);
  // 0: until stopped; else at least one period (NaN, inf and negative values are out of range).
  s.duration_s = t.number_in("duration_s", 0.0, 0.0, 1e9);
  if (s.duration_s > 0 && s.duration_s < s.period_s) {
    char text[160];
    std::snprintf(text, sizeof text, "%g s is shorter than one period (%g s); 0 runs until stopped",
                  s.duration_s, s.period_s);
    throw t.error("duration_s", text);
  }
  s.priority = static_cast<int>(t.integer_in("priority", 80, 1, 99));
  s.cpu = static_cast<int>(t.integer_in("cpu", -1, -1, 1023));
  if (s.cpu >= rt::cpu_count())
    throw t.error("cpu", "CPU " + std::to_string(s.cpu) + " does not exist: this machine has " +
                             std::to_string(rt::cpu_count()) + " (0.." +
                             std::to_string(rt::cpu_count() - 1) + "; -1: no pinning)");
  const std::string policy =
      t.choice("overrun_policy", "skip", {"skip", "catch-up", "abort-after"});
  s.policy = *overrun_policy_by_key(policy);
  s.abort_after = static_cast<int>(t.integer_in("abort_after", 10, 1, 1000000));
  s.status_interval_s = t.number_in("status_interval_s", 5.0, 0.1, 3600.0);
  s.keep_logs = static_cast<int>(t.integer("keep_logs", s.keep_logs));
  if (s.keep_logs < 0 || s.keep_logs > kMaxKeepLogs)
    throw t.error("keep_logs", "must be an integer in [0, " + std::to_string(kMaxKeepLogs) + "]");
  read_vehicle_faults(t, s);
  t.finish();
  return s;
}

ModelSettings read_model(io::config::StrictTable& t, const io::config::Overrides& overrides) {
  ModelSettings m;
  m.kind = t.choice("kind", "quarter-car", {"quarter-car", "vehicle", "combination"});
  if (m.kind == "vehicle") {  // vehicle file + road keys (rig/vehicle_config)
    m.vehicle = io::config::read_vehicle_model(t, overrides.of_file(1));
    t.finish();
    return m;
  }
  if (m.kind == "combination") {  // units, joints, road keys (rig/vehicle_config)
    m.combination = io::config::read_combination_model(t, &overrides);
    t.finish();
    return m;
  }
  auto& q = m.quarter_car;
  q.grade = t.number_in("grade", q.grade, -1.0, 1.0);
  q.mass_kg = t.number_in("mass_kg", q.mass_kg, 1.0, 1e5);
  q.max_drive_torque_nm = t.number_in("max_drive_torque_nm", q.max_drive_torque_nm, 0.0, 1e5);
  q.brake_gain_nm_per_pa = t.number_in("brake_gain_nm_per_pa", q.brake_gain_nm_per_pa, 0.0, 1.0);
  t.finish();
  return m;
}

/// [road]: the road of the vehicle or of every unit of a combination, instead of the [model]
/// road_* plane (model/road/DESIGN.md).
void read_road(io::config::StrictTable& top, RigConfig& c) {
  auto road = top.optional_table("road");
  if (!road) return;
  if (auto m = top.optional_table("model")) io::config::check_no_model_road_keys(*m);
  if (!c.model.vehicle && !c.model.combination)
    throw road->error(
        "needs [model] kind = \"vehicle\" or \"combination\" (the quarter car has "
        "its own grade)");
  const model::road::RoadParams params = io::config::read_road_section(*road);
  if (c.model.vehicle) c.model.vehicle->params.road = params;
  if (c.model.combination) {
    for (auto& unit : c.model.combination->units) unit.road = params;
  }
}

/// Wheelbase and steering ratio of the configured vehicle, the path driver's defaults.
driver::PathDriverVehicle path_driver_vehicle(const ModelSettings& m) {
  driver::PathDriverVehicle v;
  if (!m.vehicle && !m.combination) return v;
  // a combination is steered by its leading unit
  const auto& p = m.vehicle ? m.vehicle->params : m.combination->units.front();
  // steered axle (the first) to the mean position of the unsteered axles
  double rear_x_m = 0;
  int rear_count = 0;
  for (const auto& a : p.axles) {
    if (a.steered) continue;
    rear_x_m += a.position_x_m;
    ++rear_count;
  }
  if (!p.axles.empty() && rear_count > 0)
    v.wheelbase_m = p.axles.front().position_x_m - rear_x_m / rear_count;
  // road wheel steer = rack travel / steering arm, rack travel = i_SB * wheel angle
  if (p.steering.rack_per_pinion_m_per_rad > 0)
    v.steering_ratio = p.steering.steering_arm_m / p.steering.rack_per_pinion_m_per_rad;
  return v;
}

/// [driver]: a table or a path driver. A table column must not be routed to CAN.
void read_driver(io::config::StrictTable& t, const RoutingRequests& requests,
                 const RouteLocations& routes, RigConfig& c) {
  const std::string kind = t.choice("kind", "table", {"table", "path"});
  if (kind == "path") {
    c.path_driver = driver::read_path_driver(t, path_driver_vehicle(c.model));
    return;
  }
  c.driver = driver::read_table_driver(t, *c.catalogue);
  for (const std::size_t slot : c.driver->columns) {
    if (requests[slot] == RouteRequest::kCan)
      throw t.error("columns", "'" + routes[slot].name + "' is routed to CAN in [routing]");
  }
}

/// The inputs the configured driver and the events can write.
io::InputSet driver_writes(const RigConfig& c) {
  io::InputSet s = driver::event_inputs(c.events);
  if (c.path_driver) s |= driver::path_driver_inputs();
  if (c.driver) s |= driver::table_driver_inputs(*c.driver);
  return s;
}

/// An event must not set an input [routing] gives to CAN (the ECU's value would be overwritten).
void check_event_routes(const RigConfig& c, const RoutingRequests& requests,
                        const RouteLocations& routes) {
  for (const auto& e : c.events) {
    for (const auto& set : e.set) {
      if (requests[set.slot] == RouteRequest::kCan)
        throw io::config::ConfigError(set.at + ": [[event]] '" + e.name + "' do.set " + set.name +
                                      ": routed to CAN in [routing] (" + routes[set.slot].at +
                                      "); an event sets inputs the driver side feeds");
    }
  }
}

/// Where each input routed to CAN is; without a [can] section such a route is an error (the
/// input would never be written).
void locate_can_routes(const io::config::StrictTable& routing, const RoutingRequests& requests,
                       const RouteLocations& routes, RigConfig& c) {
  for (std::size_t i = 0; i < requests.size(); ++i) {
    if (requests[i] != RouteRequest::kCan) continue;
    if (!c.can)
      throw io::config::ConfigError(routes[i].at + ": " + routing.context() + " " + routes[i].name +
                                    ": routed to \"can\", but there is no [can] section (no "
                                    "mapping receives it; add [can] or route it to \"driver\")");
    c.can_route_at[i] = routes[i];
  }
}

/// The units whose vehicle files a --set may name: 1 for a vehicle, the combination's count.
void check_override_files(const io::config::Overrides& overrides, const ModelSettings& m) {
  const int units = m.vehicle       ? 1
                    : m.combination ? static_cast<int>(m.combination->units.size())
                                    : 0;
  overrides.check_files(units, m.combination.has_value());
}

}  // namespace

io::signals::ModelShape model_shape(const ModelSettings& model) {
  io::signals::ModelShape shape;
  shape.axle_count = {1, 0, 0, 0};  // the quarter car
  if (model.vehicle) {
    shape.axle_count[0] = static_cast<int>(model.vehicle->params.axles.size());
    shape.differential_count =
        model::vehicle::differential::differential_count(model.vehicle->params);
    shape.body_count = static_cast<int>(model.vehicle->params.free_bodies.size());
  }
  if (model.combination) {
    const auto& units = model.combination->units;
    shape.unit_count = static_cast<int>(units.size());
    for (std::size_t k = 0; k < units.size() && k < shape.axle_count.size(); ++k)
      shape.axle_count[k] = static_cast<int>(units[k].axles.size());
    shape.joint_count = static_cast<int>(model.combination->joints.size());
    if (!units.empty()) {
      shape.differential_count = model::vehicle::differential::differential_count(units[0]);
      shape.body_count = static_cast<int>(units[0].free_bodies.size());
    }
  }
  return shape;
}

RigConfig load_config(const std::filesystem::path& file, const io::config::Overrides& overrides) {
  toml::table doc = io::config::load_toml_file(file);
  io::config::apply_overrides(overrides.of_file(0), doc, file);
  io::config::StrictTable top(doc, file, "top level");
  RigConfig c;
  c.file = file;
  if (auto t = top.optional_table("rig")) c.rig = read_rig(*t);
  if (auto t = top.optional_table("model")) c.model = read_model(*t, overrides);
  check_override_files(overrides, c.model);
  read_road(top, c);
  c.catalogue = std::make_shared<const io::signals::Catalogue>(model_shape(c.model));
  // Routing before the driver: a table column must not be routed to CAN.
  RoutingRequests requests{};
  RouteLocations routes{};
  std::optional<io::config::StrictTable> routing = top.optional_table("routing");
  if (routing) requests = read_routing(*routing, *c.catalogue, &routes);
  if (auto t = top.optional_table("driver")) read_driver(*t, requests, routes, c);
  if (auto t = top.optional_table("can"))
    c.can = io::can::bridge::read_can_settings(*t, c.catalogue);
  if (routing) locate_can_routes(*routing, requests, routes, c);
  if (auto t = top.optional_table("lcm")) c.lcm = io::lcm::read_lcm_settings(*t, c.catalogue);
  c.events = driver::read_events(top, *c.catalogue);
  check_event_routes(c, requests, routes);
  const driver::PathDriverVehicle geometry = path_driver_vehicle(c.model);
  c.kpis = kpi::read_kpis(top, *c.catalogue, {geometry.wheelbase_m, geometry.steering_ratio});
  top.finish();  // unknown top-level sections
  c.routing = resolve_routing(requests, driver_writes(c));
  return c;
}

}  // namespace rig
