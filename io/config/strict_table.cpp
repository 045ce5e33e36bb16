#include "io/config/strict_table.h"

#include <algorithm>
#include <sstream>

#include "io/config/input_file.h"
#include "io/config/overrides.h"

namespace rig::io::config {

toml::table load_toml_file(const std::filesystem::path& file) {
  const std::string text = read_input_file(file);  // a regular file of bounded size
  try {
    return toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << file.string() << ":" << e.source().begin.line << ": " << e.description();
    throw ConfigError(msg.str());
  }
}

StrictTable::StrictTable(const toml::table& table, std::filesystem::path file, std::string context)
    : table_(&table), file_(std::move(file)), context_(std::move(context)) {}

std::string StrictTable::where(const toml::source_region& region) const {
  // a value put in by --set KEY=VALUE (io/config/overrides.h) is named by it
  if (region.path && is_override_source(*region.path)) return *region.path;
  const auto line = region.begin.line > 0 ? region.begin.line : 1;
  return file_.string() + ":" + std::to_string(line);
}

ConfigError StrictTable::error(std::string_view key, std::string_view what) const {
  const toml::node* node = table_->get(key);
  const auto& region = node != nullptr ? node->source() : table_->source();
  return ConfigError(where(region) + ": " + context_ + " " + std::string(key) + ": " +
                     std::string(what));
}

std::string StrictTable::location(std::string_view key) const {
  const toml::node* node = table_->get(key);
  return where(node != nullptr ? node->source() : table_->source());
}

ConfigError StrictTable::error(std::string_view what) const {
  return ConfigError(where(table_->source()) + ": " + context_ + ": " + std::string(what));
}

ConfigError StrictTable::error_at(const toml::node& node, std::string_view key,
                                  std::string_view what) const {
  return ConfigError(where(node.source()) + ": " + context_ + " " + std::string(key) + ": " +
                     std::string(what));
}

bool StrictTable::has(std::string_view key) const { return table_->contains(key); }

const toml::node& StrictTable::require(std::string_view key) {
  const toml::node* node = table_->get(key);
  if (node == nullptr) throw error(key, "missing required key");
  used_.emplace_back(key);
  return *node;
}

double StrictTable::number(std::string_view key) {
  const toml::node& node = require(key);
  if (auto v = node.value_exact<double>()) return *v;
  if (auto i = node.value_exact<int64_t>()) return static_cast<double>(*i);
  throw error(key, "expected a number");
}

double StrictTable::number(std::string_view key, double fallback) {
  return has(key) ? number(key) : fallback;
}

double StrictTable::number_in(std::string_view key, double min, double max) {
  const double v = number(key);
  if (!(v >= min && v <= max)) {
    std::ostringstream msg;
    msg << "value " << v << " out of range [" << min << ", " << max << "]";
    throw error(key, msg.str());
  }
  return v;
}

double StrictTable::number_in(std::string_view key, double fallback, double min, double max) {
  return has(key) ? number_in(key, min, max) : fallback;
}

long long StrictTable::integer(std::string_view key) {
  const toml::node& node = require(key);
  if (auto i = node.value_exact<int64_t>()) return *i;
  std::ostringstream msg;
  msg << "expected an integer";
  if (const auto f = node.value_exact<double>()) msg << ", not " << *f << " (a float)";
  throw error(key, msg.str());
}

long long StrictTable::integer(std::string_view key, long long fallback) {
  return has(key) ? integer(key) : fallback;
}

long long StrictTable::integer_in(std::string_view key, long long min, long long max) {
  const long long i = integer(key);
  if (i < min || i > max) {
    throw error(key, "value " + std::to_string(i) + " out of range [" + std::to_string(min) + ", " +
                         std::to_string(max) + "]");
  }
  return i;
}

long long StrictTable::integer_in(std::string_view key, long long fallback, long long min,
                                  long long max) {
  return has(key) ? integer_in(key, min, max) : fallback;
}

bool StrictTable::boolean(std::string_view key, bool fallback) {
  if (!has(key)) return fallback;
  const toml::node& node = require(key);
  if (auto b = node.value_exact<bool>()) return *b;
  throw error(key, "expected true or false");
}

std::string StrictTable::string(std::string_view key) {
  const toml::node& node = require(key);
  if (auto s = node.value_exact<std::string>()) return *s;
  throw error(key, "expected a string");
}

std::string StrictTable::string(std::string_view key, std::string_view fallback) {
  return has(key) ? string(key) : std::string(fallback);
}

std::string StrictTable::choice(std::string_view key, std::string_view fallback,
                                const std::vector<std::string_view>& allowed) {
  std::string v = string(key, fallback);
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    std::string list;
    for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    throw error(key, "unknown value '" + v + "' (expected one of: " + list + ")");
  }
  return v;
}

std::filesystem::path StrictTable::existing_path(std::string_view key) {
  const std::string raw_path = string(key);
  std::filesystem::path p(raw_path);
  if (p.is_relative()) p = file_.parent_path() / p;
  std::error_code ec;
  if (!std::filesystem::exists(p, ec)) {
    throw error(key, "file not found: " + p.string());
  }
  return p;
}

void StrictTable::check_length(std::string_view key, const toml::array& array,
                               std::size_t max_entries) const {
  if (array.size() > max_entries) {
    throw error(key,
                std::to_string(array.size()) + " entries, at most " + std::to_string(max_entries));
  }
}

std::vector<double> StrictTable::numbers(std::string_view key, std::size_t max_entries) {
  const toml::node& node = require(key);
  const toml::array* arr = node.as_array();
  if (arr == nullptr) throw error(key, "expected an array of numbers");
  check_length(key, *arr, max_entries);
  std::vector<double> out;
  out.reserve(arr->size());
  for (const toml::node& element : *arr) {
    if (auto v = element.value_exact<double>()) {
      out.push_back(*v);
    } else if (auto i = element.value_exact<int64_t>()) {
      out.push_back(static_cast<double>(*i));
    } else {
      throw error(key, "expected an array of numbers");
    }
  }
  return out;
}

std::vector<long long> StrictTable::integers(std::string_view key, std::size_t max_entries) {
  const toml::node& node = require(key);
  const toml::array* arr = node.as_array();
  if (arr == nullptr) throw error(key, "expected an array of integers");
  check_length(key, *arr, max_entries);
  std::vector<long long> out;
  out.reserve(arr->size());
  for (const toml::node& element : *arr) {
    const auto i = element.value_exact<int64_t>();
    if (!i) throw error_at(element, key, "expected an array of integers");
    out.push_back(*i);
  }
  return out;
}

std::vector<std::pair<std::string, const toml::node*>> StrictTable::strings(
    std::string_view key, std::size_t max_entries) {
  const toml::node& node = require(key);
  const toml::array* arr = node.as_array();
  if (arr == nullptr) throw error(key, "expected an array of strings");
  check_length(key, *arr, max_entries);
  std::vector<std::pair<std::string, const toml::node*>> out;
  out.reserve(arr->size());
  for (const toml::node& element : *arr) {
    const auto s = element.value_exact<std::string>();
    if (!s) throw error_at(element, key, "expected an array of strings");
    out.emplace_back(*s, &element);
  }
  return out;
}

std::vector<std::vector<double>> StrictTable::number_rows(std::string_view key, std::size_t columns,
                                                          std::size_t max_entries) {
  const toml::node& node = require(key);
  const toml::array* arr = node.as_array();
  const std::string expected = "expected an array of [" + std::to_string(columns) + " numbers]";
  if (arr == nullptr) throw error(key, expected);
  check_length(key, *arr, max_entries);
  std::vector<std::vector<double>> out;
  for (const toml::node& row : *arr) {
    const toml::array* r = row.as_array();
    if (r == nullptr || r->size() != columns) throw error(key, expected);
    std::vector<double>& values = out.emplace_back();
    for (const toml::node& element : *r) {
      if (auto v = element.value_exact<double>()) {
        values.push_back(*v);
      } else if (auto i = element.value_exact<int64_t>()) {
        values.push_back(static_cast<double>(*i));
      } else {
        throw error(key, expected);
      }
    }
  }
  return out;
}

std::vector<StrictTable> StrictTable::tables(std::string_view key, std::size_t max_entries) {
  const toml::node& node = require(key);
  const toml::array* arr = node.as_array();
  if (arr == nullptr) throw error(key, "expected an array of tables");
  check_length(key, *arr, max_entries);
  std::vector<StrictTable> out;
  std::size_t i = 0;
  for (const toml::node& element : *arr) {
    const toml::table* t = element.as_table();
    if (t == nullptr) throw error(key, "expected an array of tables");
    out.emplace_back(*t, file_,
                     context_ + "." + std::string(key) + "[" + std::to_string(i++) + "]");
  }
  return out;
}

StrictTable StrictTable::table(std::string_view key) {
  const toml::node& node = require(key);
  const toml::table* t = node.as_table();
  if (t == nullptr) throw error(key, "expected a table");
  return StrictTable(*t, file_, "[" + std::string(key) + "]");
}

std::optional<StrictTable> StrictTable::optional_table(std::string_view key) {
  if (!has(key)) return std::nullopt;
  return table(key);
}

void StrictTable::finish() const {
  for (auto&& [key, node] : *table_) {
    const std::string_view k = key.str();
    if (std::find(used_.begin(), used_.end(), k) == used_.end()) {
      throw ConfigError(where(node.source()) + ": " + context_ + ": unknown key '" +
                        std::string(k) + "'");
    }
  }
}

}  // namespace rig::io::config
