#pragma once
/// @file
/// An open-loop driver: a time table of named input signals, linearly interpolated in time and
/// held constant before the first and after the last row. A cell `nan`: the input is not given
/// (written invalid) between the rows before and after it; for the steering angle in angle mode
/// the robot then lets go of the wheel (model::vehicle::SteeringParams::angle_from_input).

#include <cstddef>
#include <vector>

#include "io/config/strict_table.h"
#include "io/signals/catalogue.h"
#include "rig/driver/driver.h"

namespace rig::driver {

struct TableDriverParams {
  std::vector<std::size_t> columns;  ///< the input slots (model/signals.h), in column order
  std::vector<double> times_s;       ///< strictly increasing
  std::vector<double> values;        ///< row-major, times_s.size() x columns.size()
};

/// Reads `[driver] kind = "table"`: columns = ["time_s", <input names>...], rows = [[t, v...]...];
/// a column names an input of `catalogue` by name or alias (io/signals). Throws
/// ConfigError(file:line) on unknown names (with the closest ones), outputs, ragged or unsorted
/// rows.
TableDriverParams read_table_driver(
    io::config::StrictTable& driver_table,
    const io::signals::Catalogue& catalogue = io::signals::Catalogue::two_axle_vehicle());

/// What a table driver can write: its columns.
io::InputSet table_driver_inputs(const TableDriverParams& params);

class TableDriver final : public Driver {
 public:
  /// `feeds`: the inputs it writes (default: all its columns).
  explicit TableDriver(TableDriverParams params);
  TableDriver(TableDriverParams params, const io::InputSet& feeds);
  /// Writes each column it feeds; O(log rows), no allocation.
  void update(double sim_time_s, model::Signals& signals) noexcept override;

 private:
  TableDriverParams params_;
};

}  // namespace rig::driver
