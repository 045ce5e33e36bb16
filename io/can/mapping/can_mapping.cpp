#include "io/can/mapping/can_mapping.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include "io/can/dbc/dbc_parser.h"
#include "io/can/dbc/signal_codec.h"
#include "io/can/mapping/protection_config.h"
#include "io/can/mapping/restbus.h"

namespace rig::io::can::mapping {
namespace {

std::size_t message_index(config::StrictTable& t, const dbc::Database& db) {
  const std::string name = t.string("message");
  for (std::size_t i = 0; i < db.messages.size(); ++i) {
    if (db.messages[i].name == name) return i;
  }
  throw t.error("message", "no message '" + name + "' in " + db.file);
}

std::size_t signal_index(config::StrictTable& t, std::string_view key, const dbc::MessageDef& m) {
  const std::string name = t.string(key);
  for (std::size_t i = 0; i < m.signals.size(); ++i) {
    if (m.signals[i].name == name) return i;
  }
  throw t.error(key, "no signal '" + name + "' in message " + m.name);
}

/// model = dbc * scale for each named conversion.
double named_scale(config::StrictTable& t) {
  const std::string c = t.choice(
      "convert", "none",
      {"none", "deg_to_rad", "kph_to_mps", "bar_to_pa", "rpm_to_radps", "percent_to_ratio"});
  if (c == "deg_to_rad") return std::numbers::pi / 180.0;
  if (c == "kph_to_mps") return 1.0 / 3.6;
  if (c == "bar_to_pa") return 1e5;
  if (c == "rpm_to_radps") return 2.0 * std::numbers::pi / 60.0;
  if (c == "percent_to_ratio") return 0.01;
  return 1.0;
}

/// TX `invalid`: a raw bit pattern of the signal (0 .. 2^bits - 1; TOML integers are signed 64
/// bit, so a 64-bit signal takes up to 2^63 - 1).
std::uint64_t invalid_raw(config::StrictTable& t, const dbc::SignalDef& s) {
  if (s.mux_role == dbc::MuxRole::kMultiplexed)
    throw t.error("invalid", s.name + " is multiplexed: no invalid value");
  const long long raw = t.integer("invalid");
  const bool fits = s.length_bits >= 63 || raw < (1LL << s.length_bits);
  if (raw < 0 || !fits) {
    throw t.error("invalid", "raw value " + std::to_string(raw) + " does not fit the " +
                                 std::to_string(s.length_bits) + " bits of " + s.name);
  }
  return static_cast<std::uint64_t>(raw);
}

MessageBinding parse_message(config::StrictTable& t, const dbc::Database& db,
                             const signals::Catalogue& catalogue, bool rx) {
  MessageBinding b;
  b.dbc_message = message_index(t, db);
  const dbc::MessageDef& m = db.messages[b.dbc_message];
  const Protection protection = read_protection(t, m);
  b.counter = protection.counter;
  b.checksum = protection.checksum;
  b.e2e = protection.e2e;
  if (rx) {
    const double default_ms = 3.0 * m.cycle_time_ms;
    if (!t.has("timeout_ms") && m.cycle_time_ms == 0) {
      throw t.error("message " + m.name + " has no GenMsgCycleTime: give timeout_ms");
    }
    const double timeout_ms = t.number_in("timeout_ms", default_ms, 1.0, 3.6e6);
    b.timeout_ns = static_cast<std::int64_t>(std::llround(timeout_ms * 1e6));
  } else {
    if (m.cycle_time_ms == 0) {
      throw t.error("message", "message " + m.name + " has no GenMsgCycleTime, cannot be sent");
    }
    b.period_ns = static_cast<std::int64_t>(m.cycle_time_ms) * 1'000'000;
  }
  std::vector<config::StrictTable> signal_tables;
  if (t.has("signal")) signal_tables = t.tables("signal", m.signals.size());
  for (config::StrictTable& st : signal_tables) {
    SignalBinding sb;
    sb.dbc_signal = signal_index(st, "dbc", m);
    const dbc::SignalDef& s = m.signals[sb.dbc_signal];
    if (st.has("constant") && st.has("model"))
      throw st.error("constant", "give model or constant, not both");
    if (!rx && st.has("constant")) {
      sb.constant = st.number("constant");
    } else {
      const std::string name = st.string("model");
      sb.model = catalogue.lookup(st, "model", name, rx, "it cannot be received", "no model signal")
                     .binding;
      if (st.has("convert") && st.has("scale"))
        throw st.error("scale", "give convert or scale, not both");
      const double named = named_scale(st);
      sb.scale = st.number("scale", named);
      if (sb.scale == 0.0 || !std::isfinite(sb.scale)) throw st.error("scale", "must be non-zero");
      sb.offset = st.number("offset", 0.0);
      if (rx) sb.fallback = st.number("fallback", 0.0);
      if (!rx && st.has("invalid")) sb.invalid_raw = invalid_raw(st, s);
    }
    check_not_protected(st, m, protection, sb.dbc_signal);
    for (const auto& other : b.signals) {
      if (other.dbc_signal == sb.dbc_signal)
        throw st.error("dbc", "signal " + s.name + " mapped twice");
    }
    st.finish();
    b.signals.push_back(sb);
  }
  t.finish();
  return b;
}

/// The catalogue name of input slot `slot`.
std::string slot_name(const signals::Catalogue& catalogue, std::size_t slot) {
  for (const signals::Entry& e : catalogue.entries()) {
    if (e.binding.is_input() && e.binding.slot == slot) return e.name;
  }
  return "slot " + std::to_string(slot);
}

}  // namespace

CanMapping parse_can_mapping(config::StrictTable& table, const dbc::Database& database,
                             const signals::Catalogue& catalogue) {
  CanMapping mapping;
  if (table.has("rx")) {
    for (config::StrictTable& t : table.tables("rx", database.messages.size()))
      mapping.rx.push_back(parse_message(t, database, catalogue, true));
  }
  if (table.has("tx")) {
    for (config::StrictTable& t : table.tables("tx", database.messages.size()))
      mapping.tx.push_back(parse_message(t, database, catalogue, false));
  }
  expand_restbus(table, database, catalogue, mapping);  // after rx and tx: it skips or refuses theirs
  // One message per direction at most; a model input bound once.
  for (std::size_t i = 0; i < mapping.rx.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (mapping.rx[i].dbc_message == mapping.rx[j].dbc_message) {
        throw table.error(
            "rx", "message " + database.messages[mapping.rx[i].dbc_message].name + " mapped twice");
      }
    }
  }
  for (std::size_t i = 0; i < mapping.tx.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (mapping.tx[i].dbc_message == mapping.tx[j].dbc_message) {
        throw table.error(
            "tx", "message " + database.messages[mapping.tx[i].dbc_message].name + " mapped twice");
      }
    }
  }
  for (const auto& r : mapping.rx) {
    for (const auto& t : mapping.tx) {
      if (r.dbc_message == t.dbc_message) {
        throw table.error("tx", "message " + database.messages[t.dbc_message].name +
                                    " is both received ([[rx]]) and sent ([[tx]])");
      }
    }
  }
  std::vector<bool> seen(model::kSlotCount);
  for (const auto& m : mapping.rx) {
    for (const auto& s : m.signals) {
      const std::size_t k = s.model->slot;
      if (seen[k]) {
        throw table.error(
            "rx", "model signal " + slot_name(catalogue, k) + " is received from two CAN signals");
      }
      seen[k] = true;
    }
  }
  return mapping;
}

CanConfig load_can_config(const std::filesystem::path& toml_file,
                          const signals::Catalogue& catalogue) {
  const toml::table root = config::load_toml_file(toml_file);
  config::StrictTable table(root, toml_file, "[can mapping]");
  CanConfig config;
  config.database = dbc::load_dbc(table.existing_path("dbc"));
  config.mapping = parse_can_mapping(table, config.database, catalogue);
  table.finish();
  return config;
}

std::filesystem::path mapping_dbc_path(const std::filesystem::path& toml_file) {
  const toml::table root = config::load_toml_file(toml_file);
  config::StrictTable table(root, toml_file, "[can mapping]");
  return table.existing_path("dbc");
}

}  // namespace rig::io::can::mapping
