#include "rig/sweep/sweep_spec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "io/config/config_error.h"
#include "io/config/overrides.h"
#include "io/config/strict_table.h"

namespace rig::sweep {
namespace {

using io::config::ConfigError;
using io::config::StrictTable;

constexpr std::size_t kMaxAxis = 100'000;

/// A value as TOML text, what `--set KEY=VALUE` takes (tables are not values here).
std::string toml_text(const StrictTable& t, std::string_view key, const toml::node& n) {
  if (n.is_table()) throw t.error_at(n, key, "expected a value (a number, string, boolean, array)");
  if (const auto d = n.value_exact<double>()) {
    if (!std::isfinite(*d)) throw t.error_at(n, key, "values must be finite");
    char buf[40];
    for (int digits = 15; digits <= 17; ++digits) {  // the shortest text that reads back exactly
      std::snprintf(buf, sizeof buf, "%.*g", digits, *d);
      if (std::strtod(buf, nullptr) == *d) break;
    }
    std::string s = buf;  // a float stays a float in TOML: 1500 -> 1500.0
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
  }
  if (const auto text = n.value_exact<std::string>()) {  // a TOML basic string: "..."
    std::string q = "\"";
    for (const char c : *text) {
      if (c == '"' || c == '\\') q += '\\';
      if (static_cast<unsigned char>(c) < 0x20) throw t.error_at(n, key, "no control characters");
      q += c;
    }
    return q + "\"";
  }
  std::ostringstream os;
  n.visit([&](const auto& v) { os << v; });
  return os.str();
}

/// A checked key path (io/config/overrides.h) of this table's `key`.
std::string key_path(const StrictTable& t, std::string_view key, const std::string& path,
                     const toml::node& at) {
  try {
    (void)io::config::parse_override(path + "=0");
  } catch (const ConfigError& e) {
    std::string what = e.what();
    throw t.error_at(at, key, what.substr(what.find(": ") + 2));
  }
  return path;
}

/// `set = { KEY = VALUE, ... }` as KEY=VALUE texts; a dotted key is nested tables in TOML, so
/// nested tables are walked and their keys joined with '.'.
void flatten(const StrictTable& t, std::string_view key, const toml::node& node,
             const std::string& prefix, std::vector<std::string>& out) {
  if (const toml::table* table = node.as_table()) {
    for (auto&& [k, child] : *table)
      flatten(t, key, child,
              prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str()), out);
    return;
  }
  out.push_back(key_path(t, key, prefix, node) + "=" + toml_text(t, key, node));
}

std::vector<std::string> read_sets(StrictTable& t, std::string_view key) {
  std::vector<std::string> out;
  if (!t.has(key)) return out;
  const toml::node* node = t.raw().get(key);
  if (!node->is_table()) throw t.error(key, "expected a table { KEY = VALUE, ... }");
  (void)t.table(key);  // read: finish() knows it
  flatten(t, key, *node, "", out);
  if (out.empty()) throw t.error(key, "'" + std::string(key) + "' sets nothing");
  return out;
}

std::vector<std::filesystem::path> read_configs(StrictTable& top) {
  if (top.has("base") == top.has("maneuvers"))
    throw top.error("base", "give 'base' (one run configuration) or 'maneuvers' (a list of them)");
  std::vector<std::filesystem::path> out;
  if (top.has("base")) {
    out.push_back(std::filesystem::absolute(top.existing_path("base")).lexically_normal());
    return out;
  }
  for (const auto& [name, node] : top.strings("maneuvers", kMaxAxis)) {
    std::filesystem::path p(name);
    if (p.is_relative()) p = top.file().parent_path() / p;
    if (!std::filesystem::is_regular_file(p))
      throw top.error_at(*node, "maneuvers", "file not found: " + p.string());
    out.push_back(std::filesystem::absolute(p).lexically_normal());
  }
  if (out.empty()) throw top.error("maneuvers", "'maneuvers' is empty");
  return out;
}

/// One [[vary]]: `key` and `values` (of any value type: checked by the key here, by the
/// configuration's reader in each run).
SweepSpec::Vary read_one_vary(const StrictTable& v) {
  for (auto&& [k, node] : v.raw()) {
    if (k.str() != "key" && k.str() != "values")
      throw v.error(k.str(), "unknown key '" + std::string(k.str()) + "' (key, values)");
  }
  const toml::node* key = v.raw().get("key");
  if (key == nullptr || !key->is_string()) throw v.error("key", "'key' is required: a key path");
  SweepSpec::Vary x;
  x.key = key_path(v, "key", key->as_string()->get(), *key);
  const toml::array* values = v.raw()["values"].as_array();
  if (values == nullptr) throw v.error("values", "'values' is required: an array of values");
  v.check_length("values", *values, kMaxAxis);
  for (const toml::node& n : *values) x.values.push_back(toml_text(v, "values", n));
  if (x.values.empty()) throw v.error("values", "'values' is empty");
  return x;
}

std::vector<SweepSpec::Vary> read_vary(StrictTable& top) {
  std::vector<SweepSpec::Vary> out;
  if (!top.has("vary")) return out;
  for (auto& v : top.tables("vary", 64)) {
    SweepSpec::Vary x = read_one_vary(v);
    for (const auto& other : out) {
      if (other.key == x.key) throw v.error("key", "'" + x.key + "' is varied twice");
    }
    out.push_back(std::move(x));
  }
  return out;
}

std::vector<SweepSpec::Road> read_roads(StrictTable& top) {
  std::vector<SweepSpec::Road> out;
  if (!top.has("roads")) return out;
  for (auto& r : top.tables("roads", kMaxAxis)) {
    SweepSpec::Road road;
    road.name = r.string("name");
    if (road.name.empty()) throw r.error("name", "'name' must not be empty");
    road.sets = read_sets(r, "set");
    if (road.sets.empty()) throw r.error("set", "a road needs 'set' (what makes it that road)");
    for (const auto& other : out) {
      if (other.name == road.name) throw r.error("name", "duplicate road '" + road.name + "'");
    }
    r.finish();
    out.push_back(std::move(road));
  }
  return out;
}

SlurmOptions read_slurm(StrictTable& top) {
  SlurmOptions s;
  auto t = top.optional_table("slurm");
  if (!t) return s;
  s.partition = t->string("partition", "");
  s.time = t->string("time", "");
  s.cpus_per_task = static_cast<int>(t->integer_in("cpus_per_task", 1, 1, 1024));
  s.runs_per_task = static_cast<int>(t->integer_in("runs_per_task", 1, 1, 1'000'000));
  if (t->has("options")) {
    for (const auto& [o, node] : t->strings("options", 64)) {
      if (o.rfind("--", 0) != 0 || o.find('\n') != std::string::npos)
        throw t->error_at(*node, "options", "an sbatch option (--name=value) on one line");
      s.options.push_back(o);
    }
  }
  t->finish();
  return s;
}

}  // namespace

int id_width(std::size_t count) {
  int digits = 1;
  for (std::size_t n = count > 0 ? count - 1 : 0; n >= 10; n /= 10) ++digits;
  return std::max(4, digits);
}

SweepSpec load_sweep_spec(const std::filesystem::path& file) {
  const toml::table doc = io::config::load_toml_file(file);
  StrictTable top(doc, file, "sweep");
  SweepSpec s;
  s.file = std::filesystem::absolute(file);
  s.name = top.string("name", file.stem().string());
  if (s.name.empty()) throw top.error("name", "'name' must not be empty");
  s.configs = read_configs(top);
  if (top.has("duration_s")) s.duration_s = top.number_in("duration_s", 1e-6, 1e9);
  s.sets = read_sets(top, "set");
  s.roads = read_roads(top);
  s.vary = read_vary(top);
  if (top.has("seeds")) {
    for (const long long seed : top.integers("seeds", kMaxAxis)) s.seeds.push_back(seed);
    if (s.seeds.empty()) throw top.error("seeds", "'seeds' is empty");
  }
  if (top.has("seed_key")) {
    s.seed_key = top.string("seed_key");
    key_path(top, "seed_key", s.seed_key, *top.raw().get("seed_key"));
  }
  s.slurm = read_slurm(top);
  top.finish();
  (void)run_count(s);
  return s;
}

std::size_t run_count(const SweepSpec& s) {
  std::size_t n = s.configs.size();
  const auto times = [&](std::size_t k) {
    if (k == 0 || n > kMaxRuns / k)
      throw ConfigError(s.file.string() + ":1: sweep: more than " + std::to_string(kMaxRuns) +
                        " runs");
    n *= k;
  };
  times(std::max<std::size_t>(1, s.roads.size()));
  for (const auto& v : s.vary) times(v.values.size());
  times(std::max<std::size_t>(1, s.seeds.size()));
  return n;
}

std::vector<SweepRun> expand(const SweepSpec& s) {
  const std::size_t n = run_count(s);
  const int width = id_width(n);
  std::vector<SweepRun> runs;
  runs.reserve(n);
  // the axes' sizes, the last varying fastest
  std::vector<std::size_t> sizes{s.configs.size(), std::max<std::size_t>(1, s.roads.size())};
  for (const auto& v : s.vary) sizes.push_back(v.values.size());
  sizes.push_back(std::max<std::size_t>(1, s.seeds.size()));
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::size_t> at(sizes.size());
    for (std::size_t a = sizes.size(), rest = i; a-- > 0;) {
      at[a] = rest % sizes[a];
      rest /= sizes[a];
    }
    SweepRun r;
    r.index = i;
    r.id = std::to_string(i);
    r.id.insert(0, static_cast<std::size_t>(std::max(0, width - static_cast<int>(r.id.size()))),
                '0');
    r.config = s.configs[at[0]];
    r.maneuver = r.config.stem().string();
    r.sets = s.sets;
    if (!s.roads.empty()) {
      r.road = s.roads[at[1]].name;
      r.sets.insert(r.sets.end(), s.roads[at[1]].sets.begin(), s.roads[at[1]].sets.end());
    }
    for (std::size_t k = 0; k < s.vary.size(); ++k) {
      const std::string& value = s.vary[k].values[at[2 + k]];
      r.vary.emplace_back(s.vary[k].key, value);
      r.sets.push_back(s.vary[k].key + "=" + value);
    }
    if (!s.seeds.empty()) {
      r.seed = s.seeds[at.back()];
      r.sets.push_back(s.seed_key + "=" + std::to_string(*r.seed));
    }
    runs.push_back(std::move(r));
  }
  return runs;
}

}  // namespace rig::sweep
