#include "io/log/log_record.h"

#include <cstdio>
#include <ctime>

namespace rig::io::log {
namespace {

std::string iso8601(std::int64_t realtime_ns) {
  const time_t secs = static_cast<time_t>(realtime_ns / 1'000'000'000);
  tm utc{};
  gmtime_r(&secs, &utc);
  char buf[64];
  const std::size_t n = std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &utc);
  char frac[32];
  std::snprintf(frac, sizeof frac, ".%09lldZ", static_cast<long long>(realtime_ns % 1'000'000'000));
  return std::string(buf, n) + frac;
}

std::string escape(const char* text) {
  std::string out;
  for (const char* p = text; *p != '\0'; ++p) {
    const char c = *p;
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::string format_record(const LogRecord& r) {
  char buf[1024];
  std::string line = "{\"time\":\"" + iso8601(r.realtime_ns) +
                     "\",\"monotonic_ns\":" + std::to_string(r.monotonic_ns);
  if (r.kind == LogRecord::Kind::kEvent) {
    line += ",\"event\":\"" + escape(r.name.data()) + "\",\"detail\":\"" + escape(r.detail.data()) +
            "\"}";
    return line;
  }
  const CycleTiming& t = r.timing;
  std::snprintf(
      buf, sizeof buf,
      ",\"event\":\"deadline_miss\",\"cycle\":%llu,\"sim_time_s\":%.9f,\"deadline_ns\":%lld,"
      "\"lateness_ns\":%lld,\"phase_ns\":{",
      static_cast<unsigned long long>(t.cycle), t.sim_time_s, static_cast<long long>(t.deadline_ns),
      static_cast<long long>(t.lateness_ns));
  line += buf;
  for (std::size_t i = 0; i < kPhaseCount; ++i) {
    std::snprintf(buf, sizeof buf, "%s\"%s\":%lld", i == 0 ? "" : ",", kPhaseNames[i],
                  static_cast<long long>(t.phase_ns[i]));
    line += buf;
  }
  std::snprintf(
      buf, sizeof buf,
      "},\"compute_ns\":%lld,\"total_ns\":%lld,\"consecutive_misses\":%u,\"action\":\"%s\"}",
      static_cast<long long>(t.compute_ns), static_cast<long long>(t.lateness_ns + t.compute_ns),
      t.consecutive_misses, escape(r.name.data()).c_str());
  line += buf;
  return line;
}

}  // namespace rig::io::log
