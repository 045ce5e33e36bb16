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

namespace rig::kpi {

/// The computations (rig/kpi/steering_kpis.h): one per `kind`.
enum class KpiKind {
  kPeakAbs,           ///< max |signal| over the window
  kLoopWidth,         ///< |signal on rising versus - signal on falling versus| at versus = at
  kGradient,          ///< d signal / d versus, least squares over |versus - at| <= band
  kResidualFraction,  ///< |signal(to_s)| / |signal(from_s)|
};

struct KpiSpec {
  std::string name;
  KpiKind kind = KpiKind::kPeakAbs;
  std::string unit;  ///< `unit`, else derived from the signals' units
  std::string signal_name;
  io::signals::Binding signal;
  std::string versus_name;  ///< loop_width, gradient
  io::signals::Binding versus;
  double at = 0.0;    ///< loop_width, gradient: the versus value
  double band = 0.0;  ///< gradient: half-width of the fit window in versus
  double from_s = 0.0;
  double to_s = 1e300;  ///< the time window (default: the whole run)
  std::optional<double> min, max;
  std::string location;  ///< file:line of the table
};

/// Reads the top level's `[[kpi]]` array (none: empty). Throws ConfigError(file:line) with the
/// key's name on an unknown kind or key, a missing key the kind needs, an unknown signal,
/// min > max, from_s >= to_s or a duplicate name.
std::vector<KpiSpec> read_kpis(io::config::StrictTable& top, const io::signals::Catalogue& cat);

}  // namespace rig::kpi
