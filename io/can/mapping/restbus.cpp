#include "io/can/mapping/restbus.h"

#include "io/can/dbc/signal_codec.h"
#include "io/can/mapping/protection_config.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rig::io::can::mapping {
namespace {

bool contains(const std::vector<MessageBinding>& list, std::size_t message) {
  return std::any_of(list.begin(), list.end(),
                     [&](const MessageBinding& b) { return b.dbc_message == message; });
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

/// The node's name, checked against the DBC (BU_ nodes and BO_ transmitters).
std::string node_name(config::StrictTable& t, const dbc::Database& db) {
  std::string node = t.string("node");
  const bool listed = std::find(db.nodes.begin(), db.nodes.end(), node) != db.nodes.end();
  const bool sends = std::any_of(db.messages.begin(), db.messages.end(),
                                 [&](const dbc::MessageDef& m) { return m.sender == node; });
  if (!listed && !sends) {
    throw t.error("node", "no node '" + node + "' in " + db.file + " (its nodes: " +
                              (db.nodes.empty() ? std::string("none") : joined(db.nodes)) + ")");
  }
  if (!sends) throw t.error("node", "node '" + node + "' sends no message in " + db.file);
  return node;
}

/// What the restbus of `node` sends: every message it transmits with a cycle time that is not
/// received ([[rx]]: an error) nor already sent by a [[tx]] (the [[tx]] wins).
std::vector<MessageBinding> node_messages(config::StrictTable& t, const std::string& node,
                                          const dbc::Database& db, CanMapping& mapping) {
  std::vector<MessageBinding> out;
  std::vector<std::string> no_cycle;
  for (std::size_t i = 0; i < db.messages.size(); ++i) {
    const dbc::MessageDef& m = db.messages[i];
    if (m.sender != node) continue;
    if (contains(mapping.rx, i)) {
      throw t.error("node", "message " + m.name + " of node " + node +
                                " is received ([[rx]]): the restbus cannot also send it");
    }
    if (contains(mapping.tx, i)) continue;
    if (m.cycle_time_ms == 0) {
      no_cycle.push_back(m.name);
      continue;
    }
    MessageBinding b;
    b.dbc_message = i;
    b.period_ns = static_cast<std::int64_t>(m.cycle_time_ms) * 1'000'000;
    out.push_back(std::move(b));
  }
  if (!no_cycle.empty()) {
    mapping.warnings.push_back(t.location("node") + ": restbus node " + node + ": " +
                               std::to_string(no_cycle.size()) +
                               " message(s) without GenMsgCycleTime not sent: " + joined(no_cycle));
  }
  return out;
}

config::ConfigError not_sent(const config::StrictTable& mt, const std::string& name,
                             const std::string& node) {
  return mt.error("name", "'" + name + "' is not a message the restbus of node " + node +
                              " sends (a cyclic message of " + node +
                              ", neither in [[rx]] nor in [[tx]])");
}

config::ConfigError no_such_signal(const config::StrictTable& set, const std::string& key,
                                   const std::string& node) {
  return set.error(
      key, "no signal '" + key + "' in the messages the restbus of node " + node + " sends");
}

/// [[restbus.message]]: a message's protection (counter, checksum, e2e), read as for a [[tx]].
void read_overrides(config::StrictTable& t, const std::string& node, const dbc::Database& db,
                    std::vector<MessageBinding>& sent) {
  if (!t.has("message")) return;
  std::vector<bool> seen(sent.size(), false);
  for (config::StrictTable& mt : t.tables("message", sent.size())) {
    const std::string name = mt.string("name");
    const auto it = std::find_if(sent.begin(), sent.end(), [&](const MessageBinding& b) {
      return db.messages[b.dbc_message].name == name;
    });
    if (it == sent.end()) throw not_sent(mt, name, node);
    const auto k = static_cast<std::size_t>(it - sent.begin());
    if (seen[k]) throw mt.error("name", "message " + name + " is given twice");
    seen[k] = true;
    Protection p = read_protection(mt, db.messages[it->dbc_message]);
    it->counter = p.counter;
    it->checksum = std::move(p.checksum);
    it->e2e = p.e2e;
    mt.finish();
  }
}

/// True if DBC signal `k` of `m` shares bits with what b's protection writes.
bool is_protected(const MessageBinding& b, const dbc::MessageDef& m, std::size_t k) {
  const auto written = protection_mask(Protection{b.counter, b.checksum, b.e2e}, m);
  std::array<std::uint8_t, 64> mine{};
  dbc::SignalCodec(m.signals[k]).insert_raw(~std::uint64_t{0}, mine.data());
  for (std::size_t i = 0; i < mine.size(); ++i) {
    if ((mine[i] & written[i]) != 0) return true;
  }
  return false;
}

/// One `set` entry: a constant (number) or a model signal (string), converted as "none".
SignalBinding set_value(config::StrictTable& set, const std::string& key,
                        const signals::Catalogue& catalogue) {
  const toml::node* v = set.raw().get(key);
  SignalBinding sb;
  if (v->is_number()) {
    sb.constant = set.number(key);
    return sb;
  }
  if (!v->is_string()) throw set.error(key, "expected a number or a model signal name");
  const std::string name = set.string(key);
  sb.model = catalogue.lookup(set, key, name, false, "", "no model signal").binding;
  return sb;
}

/// `set = { SIGNAL = ... }`: binds SIGNAL in every sent message that has it.
void read_set(config::StrictTable& t, const std::string& node, const dbc::Database& db,
              const signals::Catalogue& catalogue, std::vector<MessageBinding>& sent) {
  if (!t.has("set")) return;
  config::StrictTable set = t.table("set");
  for (const auto& entry : set.raw()) {
    const std::string key(entry.first.str());
    const SignalBinding value = set_value(set, key, catalogue);
    bool found = false;
    for (MessageBinding& b : sent) {
      const dbc::MessageDef& m = db.messages[b.dbc_message];
      const auto* s = m.find_signal(key);
      if (s == nullptr) continue;
      found = true;
      SignalBinding sb = value;
      sb.dbc_signal = static_cast<std::size_t>(s - m.signals.data());
      if (is_protected(b, m, sb.dbc_signal)) {
        throw set.error(key, "signal " + key + " is the counter, checksum or E2E field of " +
                                 m.name + ", it cannot be set");
      }
      b.signals.push_back(sb);
    }
    if (!found) throw no_such_signal(set, key, node);
  }
  set.finish();
}

}  // namespace

void expand_restbus(config::StrictTable& table, const dbc::Database& database,
                    const signals::Catalogue& catalogue, CanMapping& mapping) {
  if (!table.has("restbus")) return;
  std::vector<std::string> nodes;
  const std::size_t max_nodes = std::max<std::size_t>(1, database.messages.size());
  for (config::StrictTable& t : table.tables("restbus", max_nodes)) {
    const std::string node = node_name(t, database);
    if (std::find(nodes.begin(), nodes.end(), node) != nodes.end())
      throw t.error("node", "node " + node + " has a [[restbus]] already");
    nodes.push_back(node);
    std::vector<MessageBinding> sent = node_messages(t, node, database, mapping);
    read_overrides(t, node, database, sent);  // before `set`: it refuses counter and checksum
    read_set(t, node, database, catalogue, sent);
    t.finish();
    for (MessageBinding& b : sent) mapping.tx.push_back(std::move(b));
  }
}

}  // namespace rig::io::can::mapping
