#include "rig/summary.h"

#include <cmath>
#include <cstdio>

#include "rig/json_text.h"
#include "rig/status_line.h"
#include "rig/vehicle_fault_text.h"

namespace rig {
namespace {

std::string fmt(const char* format, auto... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

long long ll(std::int64_t v) { return static_cast<long long>(v); }
unsigned long long ull(std::uint64_t v) { return static_cast<unsigned long long>(v); }

std::string quantiles_json(const rt::LogHistogram& h) {
  return fmt("{\"p50\":%lld,\"p99\":%lld,\"p999\":%lld,\"max\":%lld,\"count\":%llu}",
             ll(h.quantile(0.5)), ll(h.quantile(0.99)), ll(h.quantile(0.999)), ll(h.max()),
             ull(h.count()));
}

std::string bins_json(const rt::LogHistogram& h) {
  std::string out = "[";
  bool first = true;
  for (const auto& b : h.bins()) {
    out += fmt("%s{\"low_ns\":%lld,\"high_ns\":%lld,\"count\":%llu}", first ? "" : ",",
               ll(b.low_ns), ll(b.high_ns), ull(b.count));
    first = false;
  }
  return out + "]";
}

/// A decade histogram for humans: counts in [1, 10) us, [10, 100) us, ...
std::string decades(const rt::LogHistogram& h) {
  std::string out;
  std::array<std::uint64_t, 8> counts{};  // <1us, 1-10us, ..., >=1s
  for (const auto& b : h.bins()) {
    const double v = static_cast<double>(b.low_ns) / 1000.0;
    std::size_t d = v < 1.0 ? 0 : static_cast<std::size_t>(std::floor(std::log10(v))) + 1;
    if (d > 7) d = 7;
    counts[d] += b.count;
  }
  const char* labels[] = {"    <1 us",  "  1-10 us",  " 10-100 us", "0.1-1 ms ",
                          "  1-10 ms ", " 10-100 ms", "0.1-1 s  ",  "   >=1 s "};
  const std::uint64_t total = h.count() == 0 ? 1 : h.count();
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (counts[i] == 0) continue;
    const int bar =
        static_cast<int>(std::ceil(40.0 * std::log10(1.0 + static_cast<double>(counts[i])) /
                                   std::log10(1.0 + static_cast<double>(total))));
    out += fmt("    %s %10llu %s\n", labels[i], ull(counts[i]),
               std::string(static_cast<std::size_t>(bar), '#').c_str());
  }
  return out;
}

/// The CAN counters and bus state.
std::string can_json(const io::IoCounters& c) {
  return fmt(
      "{\"bus_state\": \"%s\", \"frames_received\": %llu, \"frames_sent\": %llu, "
      "\"rx_overflows\": %llu, \"timeouts\": %llu, "
      "\"checksum_failures\": %llu, \"counter_failures\": %llu, \"bad_frames\": %llu, "
      "\"unknown_frames\": %llu, "
      "\"error_frames\": %llu, \"out_of_range\": %llu, \"send_no_buffer\": %llu, "
      "\"send_dropped\": %llu, "
      "\"reopens\": %llu}",
      io::bus_state_name(c.bus_state), ull(c.frames_received), ull(c.frames_sent),
      ull(c.rx_overflows), ull(c.timeouts), ull(c.checksum_failures), ull(c.counter_failures),
      ull(c.bad_frames), ull(c.unknown_frames), ull(c.error_frames), ull(c.out_of_range),
      ull(c.send_no_buffer), ull(c.send_dropped), ull(c.reopens));
}

/// [{"output": "LCM log out/run.lcm: No space left on device", "count": 12}, ...]
std::string write_failures_json(const std::vector<io::WriteFailures>& failures) {
  std::string j = "[";
  for (std::size_t i = 0; i < failures.size(); ++i) {
    j += std::string(i == 0 ? "" : ", ") + "{\"output\": " + json_string(failures[i].what) +
         ", \"count\": " + std::to_string(failures[i].count) + "}";
  }
  return j + "]";
}

/// [{"name": "brake", "time_s": 3.215}, {"name": "stop", "time_s": null}]
std::string scenario_events_json(const std::vector<std::pair<std::string, double>>& events) {
  std::string j = "[";
  for (std::size_t i = 0; i < events.size(); ++i) {
    j += std::string(i == 0 ? "" : ", ") + "{\"name\": " + json_string(events[i].first) +
         ", \"time_s\": " + json_number(events[i].second, "%.6f") + "}";
  }
  return j + "]";
}

/// The rack-in-the-loop frame bookkeeping (which cycle answered which frame).
std::string cycle_frames_json(const CycleFrameStats& cf) {
  return fmt(
      "{\"received\": %llu, \"answered_same_cycle\": %llu, \"answered_next_cycle\": %llu, "
      "\"answered_later\": %llu, \"last_rx_cycle\": %lld, \"last_tx_cycle\": %lld, "
      "\"lockstep_waits\": %llu, \"lockstep_timeouts\": %llu, \"lockstep_wait_max_ns\": %llu}",
      ull(cf.received), ull(cf.answered_same_cycle), ull(cf.answered_next_cycle),
      ull(cf.answered_later), static_cast<long long>(cf.last_rx_cycle),
      static_cast<long long>(cf.last_tx_cycle), ull(cf.lockstep_waits), ull(cf.lockstep_timeouts),
      ull(cf.lockstep_wait_max_ns));
}

/// Every valid output signal's last value, by its catalogue name.
std::string outputs_json(const model::Signals& signals) {
  std::string j = "{";
  bool first = true;
  for (const auto& s : model::kSignalTable) {
    if (s.is_input || !signals.valid[model::index(s.id)]) continue;
    j += std::string(first ? "" : ", ") + json_string(s.name) + ": " +
         json_number(signals.value[model::index(s.id)], "%.17g");
    first = false;
  }
  return j + "}";
}

}  // namespace

std::string summary_line(const Executive& e) {
  const auto& l = e.lateness();
  const auto& c = e.compute();
  StatusFigures f;
  f.cycles = e.cycles();
  f.misses = e.deadline_misses();
  f.sim_time_s = e.sim_time_s();
  f.lateness_p50_ns = l.quantile(0.5);
  f.lateness_p99_ns = l.quantile(0.99);
  f.lateness_p999_ns = l.quantile(0.999);
  f.lateness_max_ns = l.max();
  f.compute_p50_ns = c.quantile(0.5);
  f.compute_p99_ns = c.quantile(0.99);
  f.compute_max_ns = c.max();
  f.can = e.io_counters();
  return status_line(f);
}

std::string summary_report(const Executive& e, const SummaryExtras& x) {
  const auto& info = e.run_info();
  std::string out = "rig summary (" + x.stop_reason + ")\n  " + summary_line(e) + "\n";
  out +=
      fmt("  wall %.3f s, drift (sim - loop clock) %.6f s, skipped periods %llu, snapshots dropped "
          "%llu\n",
          x.wall_time_s, e.sim_time_s() - e.loop_time_s(), ull(e.skipped_periods()),
          ull(e.snapshots_dropped()));
  out += fmt("  rt: SCHED_FIFO %s (priority %d), mlockall %s, cpu %d, policy %s%s\n",
             info.sched_fifo ? "yes" : "NO", info.priority, info.memory_locked ? "yes" : "NO",
             info.cpu, info.policy.c_str(), info.offline ? ", offline" : "");
  out += "  lateness histogram:\n" + decades(e.lateness());
  out += "  compute histogram:\n" + decades(e.compute());
  return out;
}

std::string summary_json(const Executive& e, const SummaryExtras& x) {
  const auto& info = e.run_info();
  std::string j = "{\n";
  j += fmt("  \"cycles\": %llu,\n  \"deadline_misses\": %llu,\n", ull(e.cycles()),
           ull(e.deadline_misses()));
  j += "  \"sim_time_s\": " + json_number(e.sim_time_s(), "%.9f") + ",\n";
  j += "  \"wall_time_s\": " + json_number(x.wall_time_s, "%.9f") + ",\n";
  j += "  \"drift_s\": " + json_number(e.sim_time_s() - e.loop_time_s() + 0.0, "%.9f") + ",\n";
  j += "  \"period_s\": " + json_number(info.period_s) + ",\n";
  j += fmt("  \"offline\": %s,\n", info.offline ? "true" : "false");
  j += "  \"lateness_ns\": " + quantiles_json(e.lateness()) + ",\n";
  j += "  \"compute_ns\": " + quantiles_json(e.compute()) + ",\n";
  j += "  \"phase_ns\": {";
  for (std::size_t p = 0; p < io::kPhaseCount; ++p) {
    j += fmt("%s\"%s\": ", p == 0 ? "" : ", ", io::kPhaseNames[p]) +
         quantiles_json(e.phase(static_cast<io::Phase>(p)));
  }
  j += "},\n";
  j += "  \"histogram\": {\"lateness_ns\": " + bins_json(e.lateness()) +
       ",\n                \"compute_ns\": " + bins_json(e.compute()) + "},\n";
  j +=
      fmt("  \"rt\": {\"sched_fifo\": %s, \"priority\": %d, \"memory_locked\": %s, \"cpu\": %d},\n",
          info.sched_fifo ? "true" : "false", info.priority, info.memory_locked ? "true" : "false",
          info.cpu);
  j += "  \"policy\": \"" + info.policy + "\",\n";
  j += fmt(
      "  \"skipped_periods\": %llu,\n  \"snapshots_dropped\": %llu,\n  \"events_lost\": %llu,\n",
      ull(e.skipped_periods()), ull(e.snapshots_dropped()), ull(x.events_lost));
  j += "  \"can\": " + can_json(e.io_counters()) + ",\n";
  j += "  \"cycle_frames\": " + cycle_frames_json(e.cycle_frames()) + ",\n";
  j += "  \"outputs\": " + outputs_json(e.signals()) + ",\n";
  if (e.vehicle_fault().kind != model::FaultKind::kNone) {
    j += "  \"vehicle_fault\": " + vehicle_fault_json(e.vehicle_fault(), e.fault_unit_file()) +
         ",\n";
  }
  j += "  \"kpis\": " + kpi::kpis_json(x.kpis) + ",\n";
  j += "  \"scenario_events\": " + scenario_events_json(x.scenario_events) + ",\n";
  j += "  \"config\": " + json_string(x.config_file) + ",\n  \"set\": [";
  for (std::size_t i = 0; i < x.sets.size(); ++i)
    j += (i == 0 ? "" : ", ") + json_string(x.sets[i]);
  j += "],\n";
  j += "  \"write_failures\": " + write_failures_json(x.write_failures) + ",\n";
  j += "  \"stop_reason\": " + json_string(x.stop_reason) + ",\n";
  j += fmt("  \"exit_code\": %d\n}\n", x.exit_code);
  return j;
}

}  // namespace rig
