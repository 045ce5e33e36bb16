#include "rig/run_finish.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>

#include "rig/kpi/junit.h"
#include "rig/summary.h"
#include "rig/vehicle_fault_text.h"

namespace rig {
namespace {

/// The error of a failed run ("" when it ended as asked). A held vehicle fault fails the run
/// too, at its end.
std::string failure_message(const Executive& exec, const FinishInputs& in) {
  if (exec.vehicle_fault().kind != model::FaultKind::kNone) {
    char text[400];
    format_vehicle_fault(exec.vehicle_fault(), exec.fault_unit_file().c_str(), text, sizeof text);
    return std::string(text) +
           (in.reason == StopReason::kVehicleFault ? "; stopped" : "; held until the end");
  }
  switch (in.reason) {
    case StopReason::kAbortAfter:
      return "aborted after " + std::to_string(in.abort_after) + " consecutive deadline misses";
    case StopReason::kNonFinite:
      return "the model produced a non-finite value (NaN/inf) at t = " +
             std::to_string(exec.sim_time_s()) + " s; stopped";
    default:
      return "";
  }
}

std::vector<io::WriteFailures> sink_failures(const std::vector<const io::SnapshotSink*>& sinks) {
  std::vector<io::WriteFailures> out;
  for (const io::SnapshotSink* s : sinks) {
    if (io::WriteFailures f = s->write_failures(); f.count > 0) out.push_back(std::move(f));
  }
  return out;
}

/// An event in the overrun log (if that still works) for an output that failed to write.
void log_write_failure(EventLog& log, rt::Clock& wall, const io::WriteFailures& f) {
  log.event(wall.realtime_ns(), wall.now_ns(), "write_failed",
            f.what + " (" + std::to_string(f.count) + " not written)");
}

/// Writes a whole output (the summary, the JUnit XML); false (errno set) if any of it did not
/// reach the file.
bool write_text(std::FILE* f, const std::string& json) {
  errno = 0;
  const bool ok = std::fputs(json.c_str(), f) >= 0 && std::fflush(f) == 0;
  // fsync: what the file system reports only then (an I/O error); a device (/dev/null) has none.
  return ok && std::ferror(f) == 0 && (::fsync(::fileno(f)) == 0 || errno == EINVAL);
}

/// The summary's figures that are not the executive's.
SummaryExtras summary_extras(const EventLog& log, const FinishInputs& in, const RunOptions& options,
                             rt::Clock& wall) {
  SummaryExtras x;
  x.wall_time_s = static_cast<double>(wall.now_ns() - in.wall_start_ns) * 1e-9;
  x.stop_reason = stop_reason_name(in.reason);
  x.events_lost = log.lost();
  x.config_file = options.config_file;
  x.sets = options.sets;
  if (in.kpis != nullptr) x.kpis = in.kpis->results();
  if (in.events != nullptr) {
    for (std::size_t i = 0; i < in.events->specs().size(); ++i)
      x.scenario_events.push_back({in.events->specs()[i].name, in.events->fired_at_s(i)});
  }
  return x;
}

bool any_kpi_failed(const std::vector<kpi::KpiResult>& kpis) {
  return std::any_of(kpis.begin(), kpis.end(), [](const kpi::KpiResult& k) { return !k.passed; });
}

/// 1 for a failed run; else 3 for a lost output or (with --fail-on-kpi) a failed KPI; else 0.
int exit_code(const std::string& message, const std::vector<io::WriteFailures>& failures,
              bool kpi_failed) {
  if (!message.empty()) return 1;
  return !failures.empty() ? kExitOutputLost : kpi_failed ? kExitKpiFailed : 0;
}

/// One stderr line per failed KPI ("rig: kpi NAME failed: 0.43 s outside [-, 0.35]").
void report_failed_kpis(const std::vector<kpi::KpiResult>& kpis) {
  for (const auto& k : kpis) {
    if (!k.passed) std::cerr << "rig: kpi " << k.name << " failed: " << kpi::kpi_verdict(k) << "\n";
  }
}

/// The run as a JUnit <testsuite> (rig/kpi/junit.h), named after the configuration file.
std::string junit_text(const SummaryExtras& x, const std::string& message,
                       const RunOptions& options, rt::Clock& wall) {
  kpi::JunitSuite s;
  s.name = std::filesystem::path(options.config_file).stem().string();
  s.package = "rig";
  s.timestamp =
      kpi::junit_timestamp(wall.realtime_ns() - static_cast<std::int64_t>(x.wall_time_s * 1e9));
  s.hostname = kpi::host_name();
  s.time_s = x.wall_time_s;
  s.properties.emplace_back("config", options.config_file);
  for (const auto& set : options.sets) s.properties.emplace_back("set", set);
  s.properties.emplace_back("stop_reason", x.stop_reason);
  s.kpis = x.kpis;
  s.run_error = message;
  return kpi::junit_xml({s});
}

}  // namespace

int finish_run(const Executive& exec, EventLog& log, const FinishInputs& in,
               const RunOptions& options, io::systemd::SystemdNotifier& notifier, rt::Clock& wall) {
  const std::string message = failure_message(exec, in);
  log.event(wall.realtime_ns(), wall.now_ns(), "stop",
            std::string("reason ") + stop_reason_name(in.reason) + ", cycles " +
                std::to_string(exec.cycles()) + ", misses " +
                std::to_string(exec.deadline_misses()));
  std::vector<io::WriteFailures> failures = sink_failures(in.sinks);
  for (const auto& f : failures) log_write_failure(log, wall, f);
  log.drain();  // the overrun log's own failures are known now
  if (log.write_failures() > 0)
    failures.push_back(
        {log.write_failures(), "overrun log " + options.overrun_log + ": " + log.write_error()});

  SummaryExtras extras = summary_extras(log, in, options, wall);
  extras.write_failures = failures;
  const bool kpi_failed = options.fail_on_kpi && any_kpi_failed(extras.kpis);
  extras.exit_code = exit_code(message, failures, kpi_failed);
  std::cerr.clear();  // a line dropped by a full stderr (rig/stderr_relay.h) set badbit
  std::cerr << summary_report(exec, extras);
  notifier.status(summary_line(exec));
  if (notifier.dropped() > 0) {
    std::cerr << "rig: warning: " << notifier.dropped() << " systemd notifications dropped: "
              << "NOTIFY_SOCKET " << notifier.socket_name() << " is not read\n";
  }
  if (in.summary != nullptr && !write_text(in.summary, summary_json(exec, extras)))
    failures.push_back({1, "summary " + options.summary_json + ": " + std::strerror(errno)});
  const std::string junit = junit_text(extras, message, options, wall);
  if (in.junit != nullptr && !write_text(in.junit, junit))
    failures.push_back({1, "JUnit " + options.junit + ": " + std::strerror(errno)});
  for (std::size_t i = extras.write_failures.size(); i < failures.size(); ++i)
    log_write_failure(log, wall, failures[i]);
  log.stop();
  for (const auto& f : failures)
    std::cerr << "rig: error: output lost: " << f.what << " (" << f.count << " not written)\n";
  report_failed_kpis(extras.kpis);
  if (!message.empty()) std::cerr << "rig: error: " << message << "\n";
  return exit_code(message, failures, kpi_failed);
}

}  // namespace rig
