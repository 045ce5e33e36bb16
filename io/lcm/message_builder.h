#pragma once
/// @file
/// Fills the generated LCM messages from a cycle snapshot (rig.vehicle_state_t from the field
/// table io/lcm/vehicle_state_fields.h). The messages are reused from call to call, so once their
/// arrays have grown to the vehicle's unit and wheel counts, filling them does not allocate.

#include <cstdint>
#include <span>

#include "io/lcm/lcm_settings.h"
#include "io/lcm/timing_window.h"
#include "io/snapshot.h"
#include "io/snapshot_sink.h"
#include "rig/rig_status_t.hpp"
#include "rig/signals_t.hpp"
#include "rig/vehicle_state_t.hpp"

namespace rig::io::lcm {

/// Totals the status message carries besides the window percentiles; kept by the sink.
struct StatusTotals {
  std::int64_t cycles = 0;  ///< snapshots seen plus snapshots dropped by the ring
  std::int64_t deadline_misses = 0;
  std::int32_t max_consecutive_misses = 0;
  std::int64_t snapshots_dropped = 0;
};

void fill_vehicle_state(const Snapshot& snapshot, rig::vehicle_state_t& msg);
/// The enum's slots by their names, or (`chosen` not empty) the [lcm] signals in their order.
void fill_signals(const Snapshot& snapshot, std::span<const LcmSignal> chosen, rig::signals_t& msg);
void fill_status(const Snapshot& snapshot, const RunInfo& info, const StatusTotals& totals,
                 const TimingPercentiles& window, rig::rig_status_t& msg);

}  // namespace rig::io::lcm
