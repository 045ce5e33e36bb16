#include "rig/run_finish.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>
#include <utility>

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

/// Writes and closes-out the summary; false (errno set) if any of it did not reach the file.
bool write_summary(std::FILE* f, const std::string& json) {
  errno = 0;
  const bool ok = std::fputs(json.c_str(), f) >= 0 && std::fflush(f) == 0;
  // fsync: what the file system reports only then (an I/O error); a device (/dev/null) has none.
  return ok && std::ferror(f) == 0 && (::fsync(::fileno(f)) == 0 || errno == EINVAL);
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

  SummaryExtras extras;
  extras.wall_time_s = static_cast<double>(wall.now_ns() - in.wall_start_ns) * 1e-9;
  extras.stop_reason = stop_reason_name(in.reason);
  extras.events_lost = log.lost();
  extras.config_file = options.config_file;
  extras.sets = options.sets;
  if (log.write_failures() > 0)
    failures.push_back(
        {log.write_failures(), "overrun log " + options.overrun_log + ": " + log.write_error()});
  extras.write_failures = failures;
  if (in.kpis != nullptr) extras.kpis = in.kpis->results();
  if (in.events != nullptr) {
    for (std::size_t i = 0; i < in.events->specs().size(); ++i)
      extras.scenario_events.push_back({in.events->specs()[i].name, in.events->fired_at_s(i)});
  }
  extras.exit_code = !message.empty() ? 1 : failures.empty() ? 0 : kExitOutputLost;
  std::cerr.clear();  // a line dropped by a full stderr (rig/stderr_relay.h) set badbit
  std::cerr << summary_report(exec, extras);
  notifier.status(summary_line(exec));
  if (notifier.dropped() > 0) {
    std::cerr << "rig: warning: " << notifier.dropped() << " systemd notifications dropped: "
              << "NOTIFY_SOCKET " << notifier.socket_name() << " is not read\n";
  }
  if (in.summary != nullptr && !write_summary(in.summary, summary_json(exec, extras))) {
    const io::WriteFailures f{1, "summary " + options.summary_json + ": " + std::strerror(errno)};
    log_write_failure(log, wall, f);
    failures.push_back(f);
  }
  log.stop();
  for (const auto& f : failures)
    std::cerr << "rig: error: output lost: " << f.what << " (" << f.count << " not written)\n";
  if (!message.empty()) std::cerr << "rig: error: " << message << "\n";
  return !message.empty() ? 1 : failures.empty() ? 0 : kExitOutputLost;
}

}  // namespace rig
