#pragma once
/// @file
/// The rig's configuration file: [rig] run settings, [model], [driver], [routing]. Each section
/// is read by its owner's function; unknown sections and keys are ConfigErrors with file:line.
/// The routing is resolved here, once, from [routing] and the [driver] (rig/routing.h).

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "io/can/bridge/can_settings.h"
#include "io/config/combination_file.h"
#include "io/config/overrides.h"
#include "io/config/vehicle_file.h"
#include "io/lcm/lcm_settings.h"
#include "io/signals/catalogue.h"
#include "model/paper/quarter_car_params.h"
#include "rig/driver/path_driver.h"
#include "rig/driver/scenario_events.h"
#include "rig/driver/table_driver.h"
#include "rig/kpi/kpi_spec.h"
#include "rig/overrun_policy.h"
#include "rig/routing.h"

namespace rig {

/// The range of [rig] period_s (step_s), also a whole number of nanoseconds.
inline constexpr double kMinPeriod_s = 1e-5;
inline constexpr double kMaxPeriod_s = 1.0;
inline constexpr int kMaxKeepLogs = 1000;

/// [rig]
struct RigSettings {
  double period_s = 0.001;  ///< loop period = model step size
  double duration_s = 0.0;  ///< 0: run until stopped
  int priority = 80;        ///< SCHED_FIFO priority
  int cpu = -1;             ///< CPU to pin the loop thread to, -1: none
  OverrunPolicy policy = OverrunPolicy::kSkip;
  int abort_after = 10;            ///< consecutive misses for kAbortAfter
  double status_interval_s = 5.0;  ///< stderr / systemd STATUS summary interval
  /// Earlier runs' output files kept as NAME.1 (the latest) .. NAME.keep_logs
  /// (io/log/output_file.h).
  int keep_logs = 10;
  /// fault_roll_limit_rad, fault_pitch_limit_rad, fault_speed_limit_mps, fault_rate_limit_radps:
  /// beyond them a vehicle's state is a fault (model/vehicle/vehicle_faults.h), every unit's.
  model::vehicle::FaultLimits fault_limits{};
  /// on_vehicle_fault: "stop" (exit 1) or "hold" (the model freezes at its last fault-free
  /// state, its outputs flagged invalid, the loop and CAN keep running).
  bool hold_on_vehicle_fault = false;
};

/// [model]
struct ModelSettings {
  std::string kind = "quarter-car";
  model::paper::QuarterCarParams quarter_car{};
  std::optional<io::config::VehicleModelSettings> vehicle;          ///< kind = "vehicle"
  std::optional<io::config::CombinationModelSettings> combination;  ///< kind = "combination"
};

struct RigConfig {
  std::filesystem::path file;
  RigSettings rig;
  ModelSettings model;
  std::optional<driver::TableDriverParams> driver;      ///< [driver] kind = "table"
  std::optional<driver::PathDriverParams> path_driver;  ///< [driver] kind = "path"
  /// Which source feeds each input: [routing], and the inputs the driver writes.
  Routing routing;
  /// The signal catalogue of the configured model (io/signals): what every name binds to.
  std::shared_ptr<const io::signals::Catalogue> catalogue;
  io::lcm::LcmSettings lcm;  ///< [lcm] (optional): URL, channel prefix, rates, signals
  std::optional<io::can::bridge::CanSettings> can;  ///< [can], read by io/can's read_can_settings
  /// `file:line` and name of each [routing] entry `= "can"` ("" for the others), for errors
  /// found when the mapping is loaded (an input routed to CAN that no [[rx]] signal receives).
  RouteLocations can_route_at{};
  /// [[event]]: conditions and what they do (rig/driver/scenario_events.h, docs/scenarios.md).
  std::vector<driver::EventSpec> events;
  /// [[kpi]]: what the run measures for the summary's `kpis` (rig/kpi, docs/kpis.md).
  std::vector<kpi::KpiSpec> kpis;
};

/// The units and axles the signal names follow: the vehicle's (one unit), the combination's,
/// or the quarter car's one unit of one axle.
io::signals::ModelShape model_shape(const ModelSettings& model);

/// Loads and validates a configuration file, with `overrides` (--set KEY=VALUE,
/// io/config/overrides.h) put into it and the vehicle files it names. Throws
/// ConfigError("file:line: ..." or "--set KEY=VALUE: ...").
RigConfig load_config(const std::filesystem::path& file,
                      const io::config::Overrides& overrides = {});

}  // namespace rig
