#include "rig/routing.h"

#include <string>

namespace rig {
namespace {

/// One [routing] entry `name` (a key, or the dotted path to a leaf of nested tables).
void read_route(const io::config::StrictTable& t, const toml::node& node, const std::string& name,
                const io::signals::Catalogue& catalogue, RoutingRequests& requests,
                RouteLocations& where) {
  if (const toml::table* nested = node.as_table()) {
    for (auto&& [key, child] : *nested)
      read_route(t, child, name + "." + std::string(key.str()), catalogue, requests, where);
    return;
  }
  const io::signals::Entry* e = catalogue.find(name);
  if (e == nullptr) throw t.error_at(node, name, catalogue.unknown_message(name));
  if (!e->binding.is_input())
    throw t.error_at(node, name, "'" + name + "' is an output; only inputs are routed");
  const auto source = node.value<std::string>();
  if (!source) throw t.error_at(node, name, "expected a string");
  if (*source != "driver" && *source != "can")  // as StrictTable::choice says it
    throw t.error_at(node, name, "unknown value '" + *source + "' (expected one of: driver, can)");
  const std::size_t slot = e->binding.slot;
  if (requests[slot] != RouteRequest::kNone)
    throw t.error_at(node, name, "'" + e->name + "' is routed twice (by a name and an alias)");
  requests[slot] = *source == "can" ? RouteRequest::kCan : RouteRequest::kDriver;
  where[slot] = {t.location(node), name};
}

}  // namespace

RoutingRequests read_routing(io::config::StrictTable& t, const io::signals::Catalogue& catalogue,
                             RouteLocations* where) {
  RoutingRequests requests{};
  RouteLocations at{};
  for (auto&& [key, node] : t.raw())
    read_route(t, node, std::string(key.str()), catalogue, requests, at);
  if (where != nullptr) *where = at;
  return requests;
}

Routing resolve_routing(const RoutingRequests& requests, const io::InputSet& driver_writes) {
  Routing r;
  for (std::size_t i = 0; i < model::kSlotCount; ++i) {
    if (!model::slot_is_input(i)) continue;
    if (requests[i] == RouteRequest::kCan) {
      r.source[i] = model::SignalSource::kCan;
      r.can_inputs.set(i);
    } else if (requests[i] == RouteRequest::kDriver || driver_writes[i]) {
      r.source[i] = model::SignalSource::kDriver;
      r.driver_inputs.set(i);
    }
  }
  const std::size_t assist = model::index(model::Signal::kAssistTorque);
  r.assist_from_input = r.can_inputs[assist] || driver_writes[assist];
  const std::size_t angle = model::index(model::Signal::kSteeringWheelAngleCmd);
  r.angle_from_input = r.can_inputs[angle] || r.driver_inputs[angle];
  return r;
}

}  // namespace rig
