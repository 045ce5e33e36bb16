#include "rig/routing.h"

#include <string>

namespace rig {

RoutingRequests read_routing(io::config::StrictTable& t) {
  RoutingRequests requests{};
  for (auto&& [key, node] : t.raw()) {
    const std::string name(key.str());
    const auto sig = model::signal_by_name(name);
    if (!sig) throw t.error(name, "unknown signal '" + name + "'");
    if (!model::info(*sig).is_input)
      throw t.error(name, "'" + name + "' is an output; only inputs are routed");
    const std::string src = t.choice(name, "driver", {"driver", "can"});
    requests[model::index(*sig)] = src == "can" ? RouteRequest::kCan : RouteRequest::kDriver;
  }
  t.finish();
  return requests;
}

Routing resolve_routing(const RoutingRequests& requests, const io::InputSet& driver_writes) {
  Routing r;
  for (std::size_t i = 0; i < model::index(model::kFirstOutput); ++i) {
    if (requests[i] == RouteRequest::kCan) {
      r.source[i] = model::SignalSource::kCan;
      r.can_inputs.set(i);
    } else if (requests[i] == RouteRequest::kDriver || driver_writes[i]) {
      r.source[i] = model::SignalSource::kDriver;
      r.driver_inputs.set(i);
    }
  }
  r.assist_from_input = r.can_inputs[model::index(model::Signal::kAssistTorque)];
  return r;
}

}  // namespace rig
