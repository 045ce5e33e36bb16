#include "rig/status_line.h"

#include <cstdio>

namespace rig {
namespace {

unsigned long long ull(std::uint64_t v) { return static_cast<unsigned long long>(v); }
double us(std::int64_t ns) { return static_cast<double>(ns) / 1e3; }
std::uint64_t whole_us(std::int64_t ns) {
  return ns <= 0 ? 0 : static_cast<std::uint64_t>(ns) / 1000;
}

std::string timing_text(const StatusFigures& f) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "cycles %llu, misses %llu, sim %.3f s, lateness p50/p99/p99.9/max "
                "%.1f/%.1f/%.1f/%.1f us, compute p50/p99/max %.1f/%.1f/%.1f us",
                ull(f.cycles), ull(f.misses), f.sim_time_s, us(f.lateness_p50_ns),
                us(f.lateness_p99_ns), us(f.lateness_p999_ns), us(f.lateness_max_ns),
                us(f.compute_p50_ns), us(f.compute_p99_ns), us(f.compute_max_ns));
  return buf;
}

std::string can_text(const StatusFigures& f) {
  const io::IoCounters& c = f.can;
  return "cycles " + compact_count(f.cycles) + ", misses " + compact_count(f.misses) +
         ", late max " + compact_count(whole_us(f.lateness_max_ns)) + " us, rx " +
         compact_count(c.frames_received) + " tx " + compact_count(c.frames_sent) + " to " +
         compact_count(c.timeouts) + " rej " +
         compact_count(c.counter_failures + c.checksum_failures) + " oor " +
         compact_count(c.out_of_range) + ", CAN " + io::bus_state_name(c.bus_state);
}

}  // namespace

std::string compact_count(std::uint64_t n) {
  if (n < 10000) return std::to_string(n);
  static constexpr const char* kSuffix = "kMGTPE";
  int unit = 0;
  std::uint64_t scale = 1000;  // n / scale in [1, 1000)
  while (n / scale >= 1000 && unit < 5) {
    scale *= 1000;
    ++unit;
  }
  const std::uint64_t whole = n / scale;
  char buf[32];  // at most 5 characters are written; the rest quiets -Wformat-truncation
  if (whole >= 100) {
    std::snprintf(buf, sizeof buf, "%llu%c", ull(whole), kSuffix[unit]);
  } else {
    // Three significant digits, truncated: 12345 -> 12.3k, 1999 999 -> 1.99M.
    const std::uint64_t decimals = whole >= 10 ? 1 : 2;
    const std::uint64_t frac_scale = decimals == 1 ? scale / 10 : scale / 100;
    const std::uint64_t frac = (n % scale) / frac_scale;
    std::snprintf(buf, sizeof buf, "%llu.%0*llu%c", ull(whole), static_cast<int>(decimals),
                  ull(frac), kSuffix[unit]);
  }
  return buf;
}

std::string status_line(const StatusFigures& f) {
  return f.can.bus_state == io::BusState::kDisabled ? timing_text(f) : can_text(f);
}

}  // namespace rig
