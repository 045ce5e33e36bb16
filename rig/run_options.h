#pragma once
/// @file
/// Everything `rig run` was asked for on the command line (after the configuration file).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rig {

struct RunOptions {
  std::string config_file;
  /// --set KEY=VALUE, in order (io/config/overrides.h: the key path scheme).
  std::vector<std::string> sets;
  std::string junit;         ///< --junit FILE ("" = none): the KPIs as JUnit XML
  bool fail_on_kpi = false;  ///< --fail-on-kpi: a failed KPI exits 3
  std::optional<double> duration_s;  ///< overrides [rig] duration_s
  bool offline = false;
  std::string can = "";         ///< --can IFACE|none ("" = as configured)
  std::string lcm_url = "";     ///< --lcm-url URL|none ("" = as configured)
  std::string lcm_log;          ///< --lcm-log FILE ("" = none)
  std::string overrun_log;      ///< --overrun-log FILE ("" = none)
  std::string summary_json;     ///< --summary-json FILE ("" = none)
  std::optional<int> cpu;       ///< overrides [rig] cpu
  std::optional<int> priority;  ///< overrides [rig] priority
  bool require_rt = false;
  /// --lockstep: each cycle waits, up to 100 ms, for its received cycle frame (docs/can.md).
  bool lockstep = false;
  /// Test hook (hidden --inject-stall CYCLE:MS): sleep MS ms in the model phase of CYCLE.
  std::uint64_t stall_cycle = 0;
  std::int64_t stall_ms = 0;
};

}  // namespace rig
