#pragma once
/// @file
/// How the rig names a vehicle fault (model::ModelFault, model/vehicle/vehicle_faults.h): one
/// line for the event log and the exit message, one JSON object for the summary. Units are
/// numbered from 0, as the CSV's unit<i>_ columns; unit -1 is a combination's coupling.

#include <cstddef>
#include <string>

#include "model/stepped_model.h"

namespace rig {

/// "pitch -0.6012 rad beyond +-0.6 rad at t = 1.234000 s, unit 0 (config/vehicles/sedan.toml)"
/// into `out` (truncated to `size`); no allocation (the loop thread writes the event with it).
void format_vehicle_fault(const model::ModelFault& f, const char* unit_file, char* out,
                          std::size_t size) noexcept;

/// {"kind": "pitch", "unit": 0, "file": "...", "index": -1, "time_s": ..., "value": ...,
/// "limit": ...} (value and limit null when not finite).
std::string vehicle_fault_json(const model::ModelFault& f, const std::string& unit_file);

}  // namespace rig
