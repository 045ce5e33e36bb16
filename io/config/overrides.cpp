#include "io/config/overrides.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "io/config/config_error.h"

namespace rig::io::config {
namespace {

constexpr std::string_view kSetPrefix = "--set ";

ConfigError set_error(std::string_view text, const std::string& what) {
  return ConfigError(std::string(kSetPrefix) + std::string(text) + ": " + what);
}

bool bare_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
}

/// `name` or `name[i]`.
KeySegment parse_segment(std::string_view seg, std::string_view text) {
  KeySegment s;
  const auto open = seg.find('[');
  s.name = std::string(seg.substr(0, open));
  if (s.name.empty() || !std::all_of(s.name.begin(), s.name.end(), bare_key_char))
    throw set_error(text, "key '" + std::string(seg) +
                              "' is not a bare TOML key (letters, digits, _ and -; an array of "
                              "tables as NAME[i])");
  if (open == std::string_view::npos) return s;
  const std::string_view digits = seg.substr(open + 1, seg.size() - open - 2);
  if (seg.back() != ']' || digits.empty() || digits.size() > 6 ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    throw set_error(text,
                    "'" + std::string(seg) + "': an index is NAME[i], i a whole number from 0");
  s.index = std::stoul(std::string(digits));
  return s;
}

/// `unit<k>` (k >= 1) -> k; else 0.
int unit_number(const KeySegment& s) {
  if (s.index || s.name.size() < 5 || s.name.compare(0, 4, "unit") != 0) return 0;
  const std::string digits = s.name.substr(4);
  if (digits.size() > 2 || !std::all_of(digits.begin(), digits.end(), ::isdigit)) return 0;
  return std::stoi(digits);
}

/// "v = VALUE" parsed as TOML (source "--set TEXT"), else VALUE as a TOML string.
toml::table parse_value(const Override& o) {
  const std::string source = override_source(o);
  try {
    toml::table doc = toml::parse(std::string_view("v = " + o.value), std::string(source));
    if (doc.size() == 1 && doc.contains("v")) return doc;
  } catch (const toml::parse_error&) {
  }
  std::string quoted = "v = \"";
  for (const char c : o.value) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", static_cast<unsigned>(c));
      quoted += esc;
    } else {
      quoted += c;
    }
  }
  try {
    return toml::parse(std::string_view(quoted + "\""), std::string(source));
  } catch (const toml::parse_error& e) {  // not valid UTF-8
    throw set_error(o.text, "the value is neither TOML nor text: " + std::string(e.description()));
  }
}

/// Moves `node` (of a parsed document) into `parent` at `key`: a move keeps its source.
void put(toml::table& parent, const std::string& key, toml::node& node) {
  node.visit([&](auto& n) { parent.insert_or_assign(key, std::move(n)); });
}

/// `segments` from `from` on as a dotted TOML key holding VALUE, parsed with the source of the
/// override: the tables it creates carry that source too. Returns the first segment's node.
toml::table created_path(const Override& o, std::size_t from) {
  std::string key;
  for (std::size_t i = from; i < o.path.size(); ++i) {
    if (o.path[i].index)
      throw set_error(o.text, "'" + o.path[i].name + "' does not exist, so it has no entry [" +
                                  std::to_string(*o.path[i].index) + "]");
    key += (key.empty() ? "" : ".") + ("\"" + o.path[i].name + "\"");
  }
  toml::table value = parse_value(o);
  toml::table doc = toml::parse(std::string_view(key + " = 0"), override_source(o));
  // the innermost table of the created path takes the parsed value
  toml::table* t = &doc;
  for (std::size_t i = from; i + 1 < o.path.size(); ++i) t = t->get(o.path[i].name)->as_table();
  put(*t, o.path.back().name, *value.get("v"));
  return doc;
}

std::string dotted(const Override& o, std::size_t upto) {
  std::string s;
  for (std::size_t i = 0; i <= upto && i < o.path.size(); ++i) {
    s += (i == 0 ? "" : ".") + o.path[i].name;
    if (o.path[i].index) s += "[" + std::to_string(*o.path[i].index) + "]";
  }
  return s;
}

const char* type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::boolean:
      return "a boolean";
    default:
      return "a number";
  }
}

/// The entry `seg.index` of the array `node` at `o.path[i]`.
toml::node& element(toml::node& node, const Override& o, std::size_t i,
                    const std::filesystem::path& file) {
  toml::array* arr = node.as_array();
  const std::size_t index = *o.path[i].index;
  if (arr == nullptr)
    throw set_error(o.text, "'" + o.path[i].name + "' in " + file.lexically_normal().string() +
                                " is " + type_name(node) + ", not an array to index");
  if (index >= arr->size())
    throw set_error(o.text, "'" + dotted(o, i) + "': " + o.path[i].name + " in " +
                                file.lexically_normal().string() + " has " +
                                std::to_string(arr->size()) + " entries (indices from 0)");
  return (*arr)[index];
}

void apply_one(const Override& o, toml::table& doc, const std::filesystem::path& file) {
  toml::table* t = &doc;
  for (std::size_t i = 0; i < o.path.size(); ++i) {
    const KeySegment& seg = o.path[i];
    const bool last = i + 1 == o.path.size();
    toml::node* child = t->get(seg.name);
    if (child == nullptr) {  // create the rest of the path
      toml::table created = created_path(o, i);
      put(*t, seg.name, *created.get(seg.name));
      return;
    }
    if (seg.index) child = &element(*child, o, i, file);
    if (last) {
      toml::table value = parse_value(o);
      if (seg.index) {
        toml::array* arr = t->get(seg.name)->as_array();
        value.get("v")->visit([&](auto& n) {
          arr->replace(arr->cbegin() + static_cast<std::ptrdiff_t>(*seg.index), std::move(n));
        });
      } else {
        put(*t, seg.name, *value.get("v"));
      }
      return;
    }
    t = child->as_table();
    if (t == nullptr)
      throw set_error(o.text, "'" + dotted(o, i) + "' in " + file.lexically_normal().string() +
                                  " is " + type_name(*child) + ", not a table");
  }
}

}  // namespace

std::string override_source(const Override& o) { return std::string(kSetPrefix) + o.text; }

bool is_override_source(std::string_view source_path) {
  return source_path.substr(0, kSetPrefix.size()) == kSetPrefix;
}

Override parse_override(std::string_view text) {
  Override o;
  o.text = std::string(text);
  const auto eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw set_error(text, "expected KEY=VALUE (e.g. vehicle.chassis.mass_kg=1600)");
  o.key = std::string(text.substr(0, eq));
  o.value = std::string(text.substr(eq + 1));
  std::string_view rest = text.substr(0, eq);
  while (true) {
    const auto dot = rest.find('.');
    o.path.push_back(parse_segment(rest.substr(0, dot), text));
    if (dot == std::string_view::npos) break;
    rest.remove_prefix(dot + 1);
  }
  const int unit = unit_number(o.path.front());
  o.vehicle_prefix = o.path.front().name == "vehicle" && !o.path.front().index;
  if (unit > kMaxOverrideUnit)
    throw set_error(text, "'" + o.path.front().name + "': a configuration has at most " +
                              std::to_string(kMaxOverrideUnit) + " units (unit1..unit" +
                              std::to_string(kMaxOverrideUnit) + ")");
  if (unit > 0 || o.vehicle_prefix) {
    o.file = o.vehicle_prefix ? 1 : unit;
    o.path.erase(o.path.begin());
  }
  if (o.path.empty())
    throw set_error(
        text, "'" + o.key + "' names a file, not a key in it (e.g. " + o.key + ".chassis.mass_kg)");
  if (o.file == 0 && o.path.size() == 1)
    throw set_error(text, "'" + o.key +
                              "' is not SECTION.KEY: every key of a run configuration is in a "
                              "section ([rig], [model], [driver], ...), e.g. rig.duration_s");
  return o;
}

Overrides::Overrides(const std::vector<std::string>& texts) {
  for (const auto& t : texts) all_.push_back(parse_override(t));
}

std::vector<Override> Overrides::of_file(int file) const {
  std::vector<Override> out;
  for (const auto& o : all_)
    if (o.file == file) out.push_back(o);
  return out;
}

void Overrides::check_files(int unit_count, bool combination) const {
  for (const auto& o : all_) {
    if (o.file == 0) continue;
    if (unit_count == 0)
      throw set_error(o.text,
                      "this configuration's model has no vehicle file (only its own keys "
                      "can be set: SECTION.KEY)");
    if (o.vehicle_prefix && combination)
      throw set_error(o.text, "a combination has no single vehicle file: its units are unit1.." +
                                  ("unit" + std::to_string(unit_count)));
    if (o.file > unit_count)
      throw set_error(o.text,
                      "this configuration has " + std::to_string(unit_count) + " unit" +
                          (unit_count == 1 ? " (unit1 or vehicle.)"
                                           : "s (unit1..unit" + std::to_string(unit_count) + ")"));
  }
}

void apply_overrides(const std::vector<Override>& overrides, toml::table& doc,
                     const std::filesystem::path& file) {
  for (const auto& o : overrides) apply_one(o, doc, file);
}

}  // namespace rig::io::config
