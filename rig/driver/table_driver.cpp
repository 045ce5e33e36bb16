#include "rig/driver/table_driver.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

namespace rig::driver {

namespace {

/// A table value must be finite and within its input's range (model::slot_range), or `nan` (the
/// input not given there; not for time_s): an error at load, never replaced at run time.
void check_value(const io::config::StrictTable& t, const toml::node& row, const std::string& name,
                 std::optional<std::size_t> slot, double v) {
  if (slot && std::isnan(v)) return;
  if (!std::isfinite(v)) throw t.error_at(row, "rows", name + ": value is not finite");
  if (!slot) return;
  const model::InputRange r = model::slot_range(*slot);
  if (v < r.min || v > r.max || (r.whole && v != std::floor(v))) {
    std::ostringstream msg;
    msg << name << ": " << v << " is outside [" << r.min << ", " << r.max << "]"
        << (r.whole ? " or not a whole number" : "");
    throw t.error_at(row, "rows", msg.str());
  }
}

}  // namespace

TableDriverParams read_table_driver(io::config::StrictTable& t,
                                    const io::signals::Catalogue& catalogue) {
  TableDriverParams p;
  const auto& raw = t.raw();
  // columns/rows are arrays of strings/arrays, which StrictTable has no reader for: check the
  // key set here instead of with finish().
  for (auto&& [key, node] : raw) {
    const std::string_view k = key.str();
    if (k != "kind" && k != "columns" && k != "rows")
      throw t.error(k, "unknown key '" + std::string(k) + "'");
  }
  const toml::array* columns = raw["columns"].as_array();
  if (columns == nullptr) throw t.error("columns", "'columns' must be an array of signal names");
  std::vector<std::string> names;
  for (const auto& c : *columns) {
    const auto* s = c.as_string();
    if (s == nullptr) throw t.error("columns", "'columns' must hold strings");
    names.push_back(s->get());
  }
  if (names.empty() || names.front() != "time_s")
    throw t.error("columns", "the first column must be \"time_s\"");
  for (std::size_t i = 1; i < names.size(); ++i) {
    const std::size_t slot =
        catalogue.lookup(t, "columns", names[i], true, "not an input").binding.slot;
    if (std::find(p.columns.begin(), p.columns.end(), slot) != p.columns.end())
      throw t.error("columns", "duplicate column '" + names[i] + "'");
    p.columns.push_back(slot);
  }
  const toml::array* rows = raw["rows"].as_array();
  if (rows == nullptr || rows->empty())
    throw t.error("rows", "'rows' must be a non-empty array of arrays");
  t.check_length("rows", *rows, io::config::kMaxListEntries);
  for (const auto& row_node : *rows) {
    const auto* row = row_node.as_array();
    if (row == nullptr || row->size() != names.size())
      throw t.error_at(
          row_node, "rows",
          "every row needs " + std::to_string(names.size()) + " numbers (one per column)");
    for (std::size_t i = 0; i < row->size(); ++i) {
      const auto v = (*row)[i].value<double>();
      if (!v) throw t.error_at(row_node, "rows", "rows must hold numbers");
      check_value(t, row_node, names[i], i == 0 ? std::nullopt : std::optional(p.columns[i - 1]),
                  *v);
      if (i == 0) {
        if (!p.times_s.empty() && *v <= p.times_s.back())
          throw t.error_at(row_node, "rows", "time_s must increase strictly");
        p.times_s.push_back(*v);
      } else {
        p.values.push_back(*v);
      }
    }
  }
  return p;
}

}  // namespace rig::driver

namespace rig::driver {

io::InputSet table_driver_inputs(const TableDriverParams& params) {
  io::InputSet inputs;
  for (const std::size_t slot : params.columns) inputs.set(slot);
  return inputs;
}

TableDriver::TableDriver(TableDriverParams params)
    : Driver(table_driver_inputs(params)), params_(std::move(params)) {}

TableDriver::TableDriver(TableDriverParams params, const io::InputSet& feeds)
    : Driver(feeds), params_(std::move(params)) {}

void TableDriver::update(double sim_time_s, model::Signals& signals) noexcept {
  const auto& times = params_.times_s;
  const std::size_t n_cols = params_.columns.size();
  // Row i is the last row with time <= t (clamped to the table); interpolate towards row i+1.
  const auto it = std::upper_bound(times.begin(), times.end(), sim_time_s);
  std::size_t i = it == times.begin() ? 0 : static_cast<std::size_t>(it - times.begin()) - 1;
  double w = 0.0;
  if (it != times.begin() && it != times.end()) {
    w = (sim_time_s - times[i]) / (times[i + 1] - times[i]);
  }
  for (std::size_t c = 0; c < n_cols; ++c) {
    const std::size_t slot = params_.columns[c];
    if (!feeds(slot)) continue;
    const double a = params_.values[i * n_cols + c];
    const double b = w > 0.0 ? params_.values[(i + 1) * n_cols + c] : a;
    const bool given = !std::isnan(a) && !std::isnan(b);  // a nan cell: not given next to it
    signals.value[slot] = given ? a + w * (b - a) : 0.0;
    signals.valid[slot] = given;
  }
}

}  // namespace rig::driver
