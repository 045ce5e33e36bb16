#include "io/can/dbc/dbc_database.h"

namespace rig::io::can::dbc {

const SignalDef* MessageDef::find_signal(std::string_view signal_name) const {
  for (const auto& s : signals) {
    if (s.name == signal_name) return &s;
  }
  return nullptr;
}

const MessageDef* Database::find_message(std::string_view message_name) const {
  for (const auto& m : messages) {
    if (m.name == message_name) return &m;
  }
  return nullptr;
}

const MessageDef* Database::find_message(std::uint32_t id, bool extended) const {
  for (const auto& m : messages) {
    if (m.id == id && m.extended == extended) return &m;
  }
  return nullptr;
}

}  // namespace rig::io::can::dbc
