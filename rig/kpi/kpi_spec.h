#pragma once
/// @file
/// What a maneuver file asks to be measured: its `[[kpi]]` tables (docs/kpis.md). Read once at
/// load; each names catalogue signals (io/signals), bound then, so that recording needs no
/// lookups.

#include <optional>
#include <string>
#include <vector>

#include "io/config/strict_table.h"
#include "io/signals/catalogue.h"
#include "rig/kpi/braking_kpis.h"
#include "rig/kpi/circle_kpis.h"
#include "rig/kpi/iso3888_kpis.h"

namespace rig::kpi {

/// The computations: one per `kind` (docs/kpis.md).
enum class KpiKind {
  kPeakAbs,           ///< max |signal| over the window
  kLoopWidth,         ///< |signal on rising versus - signal on falling versus| at versus = at
  kGradient,          ///< d signal / d versus, least squares over |versus - at| <= band
  kResidualFraction,  ///< |signal(to_s)| / |signal(from_s)|
  // ISO 7401 step input (step_response_kpis.h): signal = the response, versus = the input
  kResponseTime,
  kPeakResponseTime,
  kOvershoot,
  kSteadyGain,
  kUndersteerGradient,  ///< ISO 4138 constant radius (circle_kpis.h)
  kBrakingDistance,     ///< braking_kpis.h
  kMeanDeceleration,    ///< UN ECE R13-H MFDD (braking_kpis.h)
  kLanesKept,           ///< ISO 3888-1 (iso3888_kpis.h)
  kConesHit,
};

/// What the run gives the KPIs that is not in their tables: the vehicle's geometry (the
/// defaults of understeer_gradient's wheelbase_m and steering_ratio).
struct KpiVehicle {
  double wheelbase_m = 2.8;
  double steering_ratio = 16.0;
};

struct KpiSpec {
  std::string name;
  KpiKind kind = KpiKind::kPeakAbs;
  std::string unit;  ///< `unit`, else derived from the signals' units
  /// The recorded series (Series::y, x, aux): the signal measured, the one it is measured
  /// against (or a trigger), a third (a yaw angle or rate); unbound ones are not recorded.
  std::string signal_name;
  io::signals::Binding signal;
  std::string versus_name;  ///< loop_width, gradient, the ISO 7401 kinds, understeer_gradient
  io::signals::Binding versus;
  bool records_versus = false;
  std::string aux_name;  ///< understeer_gradient: the yaw rate; ISO 3888-1: the yaw angle
  io::signals::Binding aux;
  bool records_aux = false;
  double at = 0.0;    ///< loop_width, gradient: the versus value
  double band = 0.0;  ///< gradient: half-width of the fit window in versus
  double from_s = 0.0;
  double to_s = 1e300;     ///< the time window (default: the whole run)
  double steady_s = 1.0;   ///< ISO 7401: the window's last part averaged for the steady state
  double fraction = 0.9;   ///< response_time: the share of the change
  double threshold = 0.0;  ///< braking: the trigger's value at the brake point
  double stop_mps = 0.01;  ///< braking_distance: the speed that counts as stopped
  CircleParams circle;     ///< understeer_gradient
  Iso3888Params track;     ///< iso3888_lanes_kept, iso3888_cones_hit
  std::optional<double> min, max;
  std::string location;  ///< file:line of the table
};

/// Reads the top level's `[[kpi]]` array (none: empty). Throws ConfigError(file:line) with the
/// key's name on an unknown kind or key, a missing key the kind needs, an unknown signal,
/// min > max, from_s >= to_s or a duplicate name. `vehicle`: the defaults some kinds take.
std::vector<KpiSpec> read_kpis(io::config::StrictTable& top, const io::signals::Catalogue& cat,
                               const KpiVehicle& vehicle = {});

}  // namespace rig::kpi
