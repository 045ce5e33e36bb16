#include "rig/log2csv/vehicle_state_csv.h"

#include <string>
#include <type_traits>
#include <vector>

#include "io/lcm/vehicle_state_fields.h"
#include "rig/vehicle_state_t.hpp"

namespace rig::log2csv {

namespace {

using Fields = io::lcm::VehicleStateFields;
using State = rig::vehicle_state_t;

/// Element `i` of array field `name`: wheel_load_n, 3 -> wheel3_load_n.
std::string element_column(std::string_view name, std::size_t i) {
  const std::string_view group = io::lcm::group_of(name);
  std::string column(group);
  column += std::to_string(i);
  column += name.substr(group.size());
  return column;
}

template <typename Value>
void add_cell(CsvLine& line, Value value) {
  if constexpr (std::is_floating_point_v<Value>) {
    line.add(static_cast<double>(value));
  } else {
    line.add(static_cast<std::int64_t>(value));
  }
}

/// Element `i` of `v`, or an empty cell if this message has fewer elements than the first.
template <typename Value>
void add_element(CsvLine& line, const std::vector<Value>& v, std::size_t i) {
  if (i < v.size()) {
    add_cell(line, v[i]);
  } else {
    line.add_empty();
  }
}

/// The columns of an array group, element by element: unit0_x_m, unit0_y_m, ..., unit1_x_m.
/// Rows the log's layout has (a log written before a row existed lacks its columns).
using HasRow = bool (*)(std::string_view name);

template <typename Rows>
void add_array_headers(std::vector<std::string>& h, const Rows& rows, std::size_t count,
                       HasRow has) {
  for (std::size_t i = 0; i < count; ++i) {
    for (const auto& row : rows) {
      if (has(row.name)) h.push_back(element_column(row.name, i));
    }
  }
}

template <typename Rows>
void add_array_cells(CsvLine& line, const State& msg, const Rows& rows, std::size_t count,
                     HasRow has) {
  for (std::size_t i = 0; i < count; ++i) {
    for (const auto& row : rows) {
      if (has(row.name)) add_element(line, msg.*row.lcm, i);
    }
  }
}

template <typename Rows>
void add_scalar_headers(std::vector<std::string>& h, const Rows& rows, HasRow has) {
  for (const auto& row : rows) {
    if (has(row.name)) h.emplace_back(row.name);
  }
}

template <typename Rows>
void add_scalar_cells(CsvLine& line, const State& msg, const Rows& rows, HasRow has) {
  for (const auto& row : rows) {
    if (has(row.name)) add_cell(line, msg.*row.lcm);
  }
}

/// Elements of a group in `msg`: the length of its first array.
template <typename Rows>
std::size_t group_size(const State& msg, const Rows& rows) {
  return (msg.*rows[0].lcm).size();
}

class VehicleStateCsv final : public ChannelCsv {
 public:
  explicit VehicleStateCsv(const VehicleStateLayout& layout) : layout_(layout) {}
  [[nodiscard]] const char* type_name() const override { return layout_.type_name; }

  [[nodiscard]] std::string header() const override {
    std::vector<std::string> h{"timestamp_us", "sim_time_s", "monotonic_ns",  "cycle",
                               "lateness_ns",  "compute_ns", "deadline_miss", "num_units"};
    const HasRow has = layout_.has_row;
    add_array_headers(h, Fields::kUnit, units_, has);
    h.emplace_back("num_wheels");
    for (std::size_t i = 0; i < wheels_; ++i) h.push_back(element_column("wheel_unit", i));
    add_array_headers(h, Fields::kWheel, wheels_, has);
    add_array_headers(h, Fields::kWheelFlag, wheels_, has);
    add_scalar_headers(h, Fields::kVehicle, has);
    add_scalar_headers(h, Fields::kVehicleInt, has);
    h.emplace_back("num_joints");
    add_array_headers(h, Fields::kJoint, joints_, has);
    if (has("num_diffs")) {  // not in v1 and v2 logs
      h.emplace_back("num_diffs");
      add_array_headers(h, Fields::kDiff, diffs_, has);
      add_array_headers(h, Fields::kDiffFlag, diffs_, has);
    }
    if (bodies_ > 0) {  // free bodies: absent without any (the CSV of a vehicle without them)
      h.emplace_back("num_bodies");
      add_array_headers(h, Fields::kBody, bodies_, has);
      add_array_headers(h, Fields::kBodyFlag, bodies_, has);
    }
    return join_columns(h);
  }

  bool row(const Event& event, CsvLine& line) override {
    if (!layout_.decode(event, msg_)) return false;
    if (!sized_) {
      units_ = group_size(msg_, Fields::kUnit);
      wheels_ = group_size(msg_, Fields::kWheel);
      joints_ = group_size(msg_, Fields::kJoint);
      diffs_ = group_size(msg_, Fields::kDiff);
      bodies_ = group_size(msg_, Fields::kBody);
      sized_ = true;
    }
    line.add(event.timestamp_us);
    line.add(msg_.sim_time_s);
    for (std::int64_t v : {msg_.monotonic_ns, msg_.cycle, msg_.lateness_ns, msg_.compute_ns,
                           std::int64_t{msg_.deadline_miss}, std::int64_t{msg_.num_units}}) {
      line.add(v);
    }
    const HasRow has = layout_.has_row;
    add_array_cells(line, msg_, Fields::kUnit, units_, has);
    line.add(std::int64_t{msg_.num_wheels});
    for (std::size_t i = 0; i < wheels_; ++i) add_element(line, msg_.wheel_unit, i);
    add_array_cells(line, msg_, Fields::kWheel, wheels_, has);
    add_array_cells(line, msg_, Fields::kWheelFlag, wheels_, has);
    add_scalar_cells(line, msg_, Fields::kVehicle, has);
    add_scalar_cells(line, msg_, Fields::kVehicleInt, has);
    line.add(std::int64_t{msg_.num_joints});
    add_array_cells(line, msg_, Fields::kJoint, joints_, has);
    if (has("num_diffs")) {
      line.add(std::int64_t{msg_.num_diffs});
      add_array_cells(line, msg_, Fields::kDiff, diffs_, has);
      add_array_cells(line, msg_, Fields::kDiffFlag, diffs_, has);
    }
    if (bodies_ > 0) {
      line.add(std::int64_t{msg_.num_bodies});
      add_array_cells(line, msg_, Fields::kBody, bodies_, has);
      add_array_cells(line, msg_, Fields::kBodyFlag, bodies_, has);
    }
    return true;
  }

 private:
  const VehicleStateLayout& layout_;
  State msg_{};
  bool sized_ = false;
  std::size_t units_ = 0, wheels_ = 0, joints_ = 0, diffs_ = 0, bodies_ = 0;
};

}  // namespace

std::unique_ptr<ChannelCsv> make_vehicle_state_csv(const VehicleStateLayout& layout) {
  return std::make_unique<VehicleStateCsv>(layout);
}

}  // namespace rig::log2csv
