#pragma once
/// @file
/// JSON values as the rig writes them (summary, vehicle fault): strict JSON, so a non-finite
/// number (a NaN stop, an infinite lateness) is `null`, never `nan` or `-inf`.

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace rig {

/// `v` with the printf `format` (a double conversion), or null if it is not finite.
inline std::string json_number(double v, const char* format = "%.9g") {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

/// A quoted JSON string (quotes, backslashes and control characters escaped).
inline std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", static_cast<unsigned>(c));
      out += esc;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace rig
