#include "rig/driver/scenario_events.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace rig::driver {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct OpName {
  const char* name;
  CompareOp op;
};
constexpr OpName kOps[] = {{"<", CompareOp::kLess},    {"<=", CompareOp::kLessEqual},
                           {">", CompareOp::kGreater}, {">=", CompareOp::kGreaterEqual},
                           {"==", CompareOp::kEqual},  {"!=", CompareOp::kNotEqual}};

EventCondition read_when(io::config::StrictTable& e, const io::signals::Catalogue& cat) {
  if (!e.has("when")) throw e.error("when", "'when' is required: { signal, op, value, for_s }");
  io::config::StrictTable w = e.table("when");
  EventCondition c;
  c.signal_name = w.string("signal");
  c.signal = cat.lookup(w, "signal", c.signal_name).binding;
  if (!w.has("op")) throw w.error("op", "'op' is required (<, <=, >, >=, ==, !=)");
  const std::string op = w.choice("op", "", {"<", "<=", ">", ">=", "==", "!="});
  c.op = std::find_if(std::begin(kOps), std::end(kOps), [&](const OpName& n) {
           return op == n.name;
         })->op;
  c.value = w.number("value");
  if (!std::isfinite(c.value)) throw w.error("value", "must be finite");
  c.for_s = w.number_in("for_s", 0.0, 0.0, 1e9);
  w.finish();
  return c;
}

/// One `set` entry `name` (a key, or the dotted path to a leaf of nested tables: an unquoted
/// `unit1.steering.wheel_angle_cmd_rad = 0.5` is TOML's nested tables).
void read_set_entry(const io::config::StrictTable& s, const toml::node& node,
                    const std::string& name, const io::signals::Catalogue& cat,
                    std::vector<EventSet>& out) {
  if (const toml::table* nested = node.as_table()) {
    for (auto&& [key, child] : *nested)
      read_set_entry(s, child, name + "." + std::string(key.str()), cat, out);
    return;
  }
  const io::signals::Entry* e = cat.find(name);
  if (e == nullptr) throw s.error_at(node, name, cat.unknown_message(name));
  if (!e->binding.is_input())
    throw s.error_at(node, name, "'" + name + "' is an output; an event sets inputs only");
  const auto v = node.value<double>();
  if (!v) throw s.error_at(node, name, "expected a number");
  const std::size_t slot = e->binding.slot;
  const model::InputRange r = model::slot_range(slot);
  if (!std::isfinite(*v) || *v < r.min || *v > r.max || (r.whole && *v != std::floor(*v))) {
    std::ostringstream msg;
    msg << *v << " is outside [" << r.min << ", " << r.max << "]"
        << (r.whole ? " or not a whole number" : "");
    throw s.error_at(node, name, msg.str());
  }
  for (const EventSet& other : out) {
    if (other.slot == slot)
      throw s.error_at(node, name, "'" + e->name + "' is set twice (by a name and an alias)");
  }
  out.push_back({name, s.location(node), slot, *v});
}

/// `do = "stop"` or `do = { set = {...}, ramp_s = ... }`.
void read_do(io::config::StrictTable& e, const io::signals::Catalogue& cat, EventSpec& spec) {
  const char* expected = "'do' is required: \"stop\" or { set = { INPUT = VALUE, ... }, ramp_s }";
  if (!e.has("do")) throw e.error("do", expected);
  if (e.raw()["do"].is_string()) {
    if (e.string("do") != "stop")
      throw e.error("do", "unknown value '" + e.string("do") + "': " + expected);
    spec.stop = true;
    return;
  }
  if (!e.raw()["do"].is_table()) throw e.error("do", expected);
  io::config::StrictTable d = e.table("do");
  if (!d.has("set")) throw d.error("set", "'set' is required: { INPUT = VALUE, ... }");
  const io::config::StrictTable s = d.table("set");
  for (auto&& [key, node] : s.raw()) read_set_entry(s, node, std::string(key.str()), cat, spec.set);
  if (spec.set.empty()) throw d.error("set", "'set' names no input");
  spec.ramp_s = d.number_in("ramp_s", 0.0, 0.0, 1e6);
  d.finish();
}

EventSpec read_event(io::config::StrictTable& e, const io::signals::Catalogue& cat,
                     std::size_t index) {
  EventSpec spec;
  spec.location = e.location("when");
  spec.name = e.string("name", "event" + std::to_string(index));
  if (spec.name.empty()) throw e.error("name", "'name' must not be empty");
  spec.when = read_when(e, cat);
  read_do(e, cat, spec);
  e.finish();
  return spec;
}

}  // namespace

const char* compare_op_name(CompareOp op) {
  for (const auto& n : kOps)
    if (n.op == op) return n.name;
  return "?";
}

bool compare(CompareOp op, double v, double value) noexcept {
  switch (op) {
    case CompareOp::kLess:
      return v < value;
    case CompareOp::kLessEqual:
      return v <= value;
    case CompareOp::kGreater:
      return v > value;
    case CompareOp::kGreaterEqual:
      return v >= value;
    case CompareOp::kEqual:
      return v == value;
    case CompareOp::kNotEqual:
      return v != value && !std::isnan(v);
  }
  return false;
}

std::vector<EventSpec> read_events(io::config::StrictTable& top,
                                   const io::signals::Catalogue& catalogue) {
  std::vector<EventSpec> out;
  if (!top.has("event")) return out;
  auto tables = top.tables("event", kMaxEvents);
  for (std::size_t i = 0; i < tables.size(); ++i) {
    EventSpec spec = read_event(tables[i], catalogue, i);
    for (const auto& other : out) {
      if (other.name == spec.name)
        throw tables[i].error(
            "name", "duplicate event name '" + spec.name + "' (first at " + other.location + ")");
    }
    out.push_back(std::move(spec));
  }
  return out;
}

io::InputSet event_inputs(const std::vector<EventSpec>& events) {
  io::InputSet s;
  for (const auto& e : events)
    for (const auto& set : e.set) s.set(set.slot);
  return s;
}

EventStage::EventStage(std::vector<EventSpec> events)
    : specs_(std::move(events)),
      held_since_s_(specs_.size(), kNaN),
      fired_at_s_(specs_.size(), kNaN),
      fired_(specs_.size(), 0) {}

void EventStage::fire(std::size_t i, double t_s, const model::Signals& signals) noexcept {
  const EventSpec& e = specs_[i];
  fired_at_s_[i] = t_s;
  fired_[fired_count_++] = i;
  for (const EventSet& s : e.set) {
    Hold& h = holds_[s.slot];
    // the ramp starts where the input is (the driver's value, or an earlier event's); an input
    // nobody gave (invalid) from 0; a whole-number input (gear, ignition) steps
    const double now = signals.value[s.slot];
    h.from = signals.valid[s.slot] && std::isfinite(now) ? now : 0.0;
    h.to = s.value;
    h.t0_s = t_s;
    h.ramp_s = model::slot_range(s.slot).whole ? 0.0 : e.ramp_s;
    h.active = true;
  }
}

bool EventStage::update(double sim_time_s, const io::signals::CycleView& previous,
                        model::Signals& signals) noexcept {
  fired_count_ = 0;
  bool stop = false;
  // the conditions first, all on the same view; then the writes
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    if (!std::isnan(fired_at_s_[i])) continue;
    const EventCondition& c = specs_[i].when;
    if (!c.signal.valid(previous) || !compare(c.op, c.signal.value(previous), c.value)) {
      held_since_s_[i] = kNaN;
      continue;
    }
    if (std::isnan(held_since_s_[i])) held_since_s_[i] = sim_time_s;
    if (sim_time_s - held_since_s_[i] < c.for_s - 1e-9) continue;  // 1 ns: the time grid's sums
    fire(i, sim_time_s, signals);
    stop = stop || specs_[i].stop;
  }
  for (std::size_t slot = 0; slot < holds_.size(); ++slot) {
    const Hold& h = holds_[slot];
    if (!h.active) continue;
    const double f = h.ramp_s > 0.0 ? std::clamp((sim_time_s - h.t0_s) / h.ramp_s, 0.0, 1.0) : 1.0;
    signals.value[slot] = h.from + (h.to - h.from) * f;
    signals.valid[slot] = true;
  }
  return stop;
}

}  // namespace rig::driver
