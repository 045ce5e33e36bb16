#include "rig/kpi/kpi_spec.h"

#include <algorithm>

namespace rig::kpi {
namespace {

/// Which keys a kind reads (besides name, kind, the window, the limits and unit).
enum class Group { kSignals, kStep, kCircle, kBraking, kTrack };

struct KindName {
  const char* name;
  KpiKind kind;
  Group group;
  bool needs_versus;
  const char* unit;  ///< nullptr: derived from the signals
};
constexpr KindName kKinds[] = {
    {"peak_abs", KpiKind::kPeakAbs, Group::kSignals, false, nullptr},
    {"loop_width", KpiKind::kLoopWidth, Group::kSignals, true, nullptr},
    {"gradient", KpiKind::kGradient, Group::kSignals, true, nullptr},
    {"residual_fraction", KpiKind::kResidualFraction, Group::kSignals, false, "1"},
    {"response_time", KpiKind::kResponseTime, Group::kStep, true, "s"},
    {"peak_response_time", KpiKind::kPeakResponseTime, Group::kStep, true, "s"},
    {"overshoot", KpiKind::kOvershoot, Group::kStep, true, "1"},
    {"steady_gain", KpiKind::kSteadyGain, Group::kStep, true, nullptr},
    {"understeer_gradient", KpiKind::kUndersteerGradient, Group::kCircle, false, "rad/(m/s^2)"},
    {"braking_distance", KpiKind::kBrakingDistance, Group::kBraking, false, "m"},
    {"mean_deceleration", KpiKind::kMeanDeceleration, Group::kBraking, false, "m/s^2"},
    {"iso3888_lanes_kept", KpiKind::kLanesKept, Group::kTrack, false, "1"},
    {"iso3888_cones_hit", KpiKind::kConesHit, Group::kTrack, false, "1"},
};

std::vector<std::string_view> kind_names() {
  std::vector<std::string_view> out;
  for (const auto& k : kKinds) out.emplace_back(k.name);
  return out;
}

/// A signal the kind records by its catalogue name.
io::signals::Binding fixed(const io::config::StrictTable& t, const io::signals::Catalogue& cat,
                           const std::string& name) {
  const io::signals::Entry* e = cat.find(name);
  if (e == nullptr)
    throw t.error("kind", "this model has no signal '" + name + "' (the kind needs it)");
  return e->binding;
}

/// The signal named by `key` (or `fallback` when the table has no such key).
const io::signals::Entry& bind(io::config::StrictTable& t, const io::signals::Catalogue& cat,
                               std::string_view key, const char* fallback, std::string& name,
                               io::signals::Binding& binding) {
  name = fallback != nullptr ? t.string(key, fallback) : t.string(key);
  const io::signals::Entry* e = cat.find(name);
  if (e == nullptr && !t.has(key))
    throw t.error("kind", "this model has no signal '" + name + "' (the kind needs it)");
  if (e == nullptr) e = &cat.lookup(t, key, name);
  binding = e->binding;
  return *e;
}

/// peak_abs, loop_width, gradient, residual_fraction: `signal`, `versus`, `at`, `band`.
std::string read_signals(io::config::StrictTable& t, const io::signals::Catalogue& cat,
                         const KindName& kn, KpiSpec& k) {
  const io::signals::Entry& y = bind(t, cat, "signal", nullptr, k.signal_name, k.signal);
  std::string x_unit;
  if (kn.needs_versus) {
    if (!t.has("versus"))
      throw t.error("versus",
                    "kind = \"" + std::string(kn.name) + "\" needs 'versus' (the x signal)");
    x_unit = bind(t, cat, "versus", nullptr, k.versus_name, k.versus).unit;
    k.records_versus = true;
    k.at = t.number("at", 0.0);
  }
  if (k.kind == KpiKind::kGradient) k.band = t.number_in("band", 1e-300, 1e300);
  if (k.kind == KpiKind::kResidualFraction && (!t.has("from_s") || !t.has("to_s")))
    throw t.error("to_s", "kind = \"residual_fraction\" needs 'from_s' (the reference) and 'to_s'");
  return k.kind == KpiKind::kGradient ? y.unit + "/(" + x_unit + ")" : y.unit;
}

/// The ISO 7401 kinds: `signal` (the response), `versus` (the input), `steady_s`, `fraction`.
std::string read_step(io::config::StrictTable& t, const io::signals::Catalogue& cat,
                      const KindName& kn, KpiSpec& k) {
  const io::signals::Entry& y = bind(t, cat, "signal", nullptr, k.signal_name, k.signal);
  if (!t.has("versus"))
    throw t.error("versus", "kind = \"" + std::string(kn.name) +
                                "\" needs 'versus' (the input: the steering-wheel angle)");
  const io::signals::Entry& x = bind(t, cat, "versus", nullptr, k.versus_name, k.versus);
  k.records_versus = true;
  k.steady_s = t.number_in("steady_s", 1.0, 1e-3, 1e6);
  if (k.kind == KpiKind::kResponseTime) k.fraction = t.number_in("fraction", 0.9, 0.01, 1.0);
  return y.unit + "/(" + x.unit + ")";
}

/// understeer_gradient: `signal` (the steering-wheel angle), the plateaus and the vehicle.
void read_circle(io::config::StrictTable& t, const io::signals::Catalogue& cat,
                 const KpiVehicle& vehicle, KpiSpec& k) {
  bind(t, cat, "signal", "unit1.steering.wheel_angle_rad", k.signal_name, k.signal);
  k.versus_name = "unit1.speed_x_mps";  // the speed and the yaw rate: a_y = v r, R = v / r
  k.versus = fixed(t, cat, k.versus_name);
  k.aux_name = "unit1.yaw_rate_radps";
  k.aux = fixed(t, cat, k.aux_name);
  k.records_versus = k.records_aux = true;
  CircleParams& c = k.circle;
  if (!t.has("plateau_s"))
    throw t.error("plateau_s",
                  "kind = \"understeer_gradient\" needs 'plateau_s' (the length of "
                  "each steady state: the driver's speed_step_duration_s)");
  c.plateau_s = t.number_in("plateau_s", 1e-3, 1e6);
  c.steady_s = t.number_in("steady_s", std::min(3.0, c.plateau_s), 1e-3, c.plateau_s);
  c.speed_band_mps = t.number_in("speed_band_mps", 0.1, 0.0, 100.0);
  c.ay_min_mps2 = t.number_in("ay_min_mps2", 0.0, 0.0, 100.0);
  c.ay_max_mps2 = t.number_in("ay_max_mps2", 4.0, c.ay_min_mps2, 100.0);
  c.wheelbase_m = t.number_in("wheelbase_m", vehicle.wheelbase_m, 0.1, 100.0);
  c.steering_ratio = t.number_in("steering_ratio", vehicle.steering_ratio, 0.1, 1000.0);
}

/// braking_distance, mean_deceleration: `signal` (the speed), `trigger`, `threshold`,
/// `stop_mps`.
void read_braking(io::config::StrictTable& t, const io::signals::Catalogue& cat, KpiSpec& k) {
  bind(t, cat, "signal", "unit1.speed_x_mps", k.signal_name, k.signal);
  if (t.has("trigger")) {
    bind(t, cat, "trigger", nullptr, k.versus_name, k.versus);
    k.records_versus = true;
    if (!t.has("threshold"))
      throw t.error("threshold", "'trigger' needs 'threshold' (its value at the brake point)");
    k.threshold = t.number("threshold");
  }
  if (k.kind == KpiKind::kBrakingDistance) k.stop_mps = t.number_in("stop_mps", 0.01, 0.0, 10.0);
}

/// The ISO 3888-1 kinds: the track and the vehicle's outline.
void read_track(io::config::StrictTable& t, const io::signals::Catalogue& cat, KpiSpec& k) {
  k.versus_name = "unit1.position_x_m";
  k.versus = fixed(t, cat, k.versus_name);
  k.signal_name = "unit1.position_y_m";
  k.signal = fixed(t, cat, k.signal_name);
  k.aux_name = "unit1.yaw_rad";
  k.aux = fixed(t, cat, k.aux_name);
  k.records_versus = k.records_aux = true;
  Iso3888Params& p = k.track;
  p.start_x_m = t.number_in("start_x_m", -1e6, 1e6);
  p.lane_offset_m = t.number_in("lane_offset_m", 3.5, -100.0, 100.0);
  p.vehicle_width_m = t.number_in("vehicle_width_m", 0.1, 10.0);
  p.vehicle_length_m = t.number_in("vehicle_length_m", 0.1, 50.0);
  p.cg_to_front_m = t.number_in("cg_to_front_m", 0.0, p.vehicle_length_m);
  if (k.kind == KpiKind::kConesHit) {
    p.cone_spacing_m = t.number_in("cone_spacing_m", 5.0, 0.1, 100.0);
    p.cone_radius_m = t.number_in("cone_radius_m", 0.15, 0.0, 1.0);
  }
}

KpiSpec read_kpi(io::config::StrictTable& t, const io::signals::Catalogue& cat,
                 const KpiVehicle& vehicle) {
  KpiSpec k;
  k.location = t.location("name");
  k.name = t.string("name");
  if (k.name.empty()) throw t.error("name", "'name' must not be empty");
  if (!t.has("kind")) throw t.error("kind", "'kind' is required (docs/kpis.md lists them)");
  const std::string kind = t.choice("kind", "", kind_names());
  const KindName& kn = *std::find_if(std::begin(kKinds), std::end(kKinds),
                                     [&](const KindName& n) { return kind == n.name; });
  k.kind = kn.kind;
  k.from_s = t.number_in("from_s", 0.0, 0.0, 1e9);
  k.to_s = t.number_in("to_s", 1e300, 0.0, 1e300);
  if (!(k.from_s < k.to_s)) throw t.error("to_s", "'to_s' must be greater than 'from_s'");
  std::string unit = kn.unit != nullptr ? kn.unit : "";
  switch (kn.group) {
    case Group::kSignals: {
      const std::string derived = read_signals(t, cat, kn, k);
      if (kn.unit == nullptr) unit = derived;
      break;
    }
    case Group::kStep: {
      const std::string derived = read_step(t, cat, kn, k);
      if (kn.unit == nullptr) unit = derived;
      break;
    }
    case Group::kCircle:
      read_circle(t, cat, vehicle, k);
      k.circle.from_s = k.from_s;
      break;
    case Group::kBraking:
      read_braking(t, cat, k);
      break;
    case Group::kTrack:
      read_track(t, cat, k);
      break;
  }
  if (t.has("min")) k.min = t.number("min");
  if (t.has("max")) k.max = t.number("max");
  if (k.min && k.max && *k.min > *k.max) throw t.error("max", "'min' must not exceed 'max'");
  k.unit = t.string("unit", unit);
  t.finish();
  return k;
}

}  // namespace

std::vector<KpiSpec> read_kpis(io::config::StrictTable& top, const io::signals::Catalogue& cat,
                               const KpiVehicle& vehicle) {
  std::vector<KpiSpec> out;
  if (!top.has("kpi")) return out;
  for (auto& t : top.tables("kpi", 64)) {
    KpiSpec k = read_kpi(t, cat, vehicle);
    for (const auto& other : out) {
      if (other.name == k.name)
        throw t.error("name",
                      "duplicate kpi name '" + k.name + "' (first at " + other.location + ")");
    }
    out.push_back(std::move(k));
  }
  return out;
}

}  // namespace rig::kpi
