#include "rig/signals_command.h"

#include <exception>
#include <ostream>

#include "io/config/config_error.h"
#include "rig/config.h"
#include "rig/json_text.h"

namespace rig {
namespace {

const char* direction_name(io::signals::Direction d) {
  return d == io::signals::Direction::kIn ? "in" : "out";
}

void write_json(const io::signals::Catalogue& catalogue, std::ostream& out) {
  out << "[";
  bool first = true;
  for (const io::signals::Entry& e : catalogue.entries()) {
    out << (first ? "\n" : ",\n") << "  {\"name\": " << json_string(e.name)
        << ", \"unit\": " << json_string(e.unit)
        << ", \"direction\": " << json_string(direction_name(e.direction))
        << ", \"min\": " << json_number(e.min, "%.17g")
        << ", \"max\": " << json_number(e.max, "%.17g") << ", \"aliases\": [";
    for (std::size_t i = 0; i < e.aliases.size(); ++i)
      out << (i == 0 ? "" : ", ") << json_string(e.aliases[i]);
    out << "]}";
    first = false;
  }
  out << "\n]\n";
}

void write_text(const io::signals::Catalogue& catalogue, std::ostream& out) {
  out << "# name\tunit\tdirection\tmin\tmax\taliases\n";
  for (const io::signals::Entry& e : catalogue.entries()) {
    const bool in = e.direction == io::signals::Direction::kIn;
    out << e.name << "\t" << e.unit << "\t" << direction_name(e.direction) << "\t"
        << (in ? json_number(e.min) : "-") << "\t" << (in ? json_number(e.max) : "-") << "\t";
    for (std::size_t i = 0; i < e.aliases.size(); ++i) out << (i == 0 ? "" : ",") << e.aliases[i];
    out << "\n";
  }
}

}  // namespace

void write_signals(const io::signals::Catalogue& catalogue, bool json, std::ostream& out) {
  if (json) {
    write_json(catalogue, out);
  } else {
    write_text(catalogue, out);
  }
}

int signals_command(const std::string& config_file, bool json, std::ostream& out,
                    std::ostream& err) {
  try {
    const RigConfig config = load_config(config_file);
    write_signals(*config.catalogue, json, out);
  } catch (const io::config::ConfigError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << config_file << ": " << e.what() << "\n";
    return 2;
  }
  return 0;
}

}  // namespace rig
