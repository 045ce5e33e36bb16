#include "rig/vehicle_fault_text.h"

#include <cmath>
#include <cstdio>

#include "rig/json_text.h"

namespace rig {
namespace {

/// The point a fault's index names: a wheel or a body point ("" for the unit as a whole).
const char* index_noun(model::FaultKind k) noexcept {
  if (k == model::FaultKind::kWheelSpin) return ", wheel ";
  if (k == model::FaultKind::kBodyGround) return ", body point ";
  if (k == model::FaultKind::kFreeBodyStops) return ", free body ";
  return "";
}

}  // namespace

void format_vehicle_fault(const model::ModelFault& f, const char* unit_file, char* out,
                          std::size_t size) noexcept {
  const std::string_view kind = model::fault_kind_name(f.kind);
  const std::string_view unit = model::fault_value_unit(f.kind);
  char where[48] = "";
  if (f.index >= 0) std::snprintf(where, sizeof where, "%s%d", index_noun(f.kind), f.index);
  char what[96];
  if (f.kind == model::FaultKind::kNonFinite) {
    std::snprintf(what, sizeof what, "non-finite state (NaN/inf)");
  } else if (f.kind == model::FaultKind::kBodyGround) {
    std::snprintf(what, sizeof what, "body below the road by %.4g m", -f.value);
  } else {
    std::snprintf(what, sizeof what, "%.*s %.6g %.*s beyond the limit %.6g %.*s",
                  static_cast<int>(kind.size()), kind.data(), f.value,
                  static_cast<int>(unit.size()), unit.data(), f.limit,
                  static_cast<int>(unit.size()), unit.data());
  }
  std::snprintf(out, size, "vehicle fault %.*s: %s at t = %.6f s, unit %d (%s)%s",
                static_cast<int>(kind.size()), kind.data(), what, f.time_s, f.unit,
                unit_file[0] != '\0' ? unit_file : "the coupling", where);
}

std::string vehicle_fault_json(const model::ModelFault& f, const std::string& unit_file) {
  return "{\"kind\": \"" + std::string(model::fault_kind_name(f.kind)) +
         "\", \"unit\": " + std::to_string(f.unit) + ", \"file\": " + json_string(unit_file) +
         ", \"index\": " + std::to_string(f.index) + ", \"time_s\": " + json_number(f.time_s) +
         ", \"value\": " + json_number(f.value) + ", \"limit\": " + json_number(f.limit) + "}";
}

}  // namespace rig
