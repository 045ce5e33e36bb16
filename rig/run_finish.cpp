#include "rig/run_finish.h"

#include <fstream>
#include <iostream>
#include <string>

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

}  // namespace

int finish_run(const Executive& exec, EventLog& log, const FinishInputs& in,
               const RunOptions& options, io::systemd::SystemdNotifier& notifier, rt::Clock& wall) {
  const std::string message = failure_message(exec, in);
  int exit_code = message.empty() ? 0 : 1;
  log.event(wall.realtime_ns(), wall.now_ns(), "stop",
            std::string("reason ") + stop_reason_name(in.reason) + ", cycles " +
                std::to_string(exec.cycles()) + ", misses " +
                std::to_string(exec.deadline_misses()));
  log.stop();

  SummaryExtras extras;
  extras.wall_time_s = static_cast<double>(wall.now_ns() - in.wall_start_ns) * 1e-9;
  extras.stop_reason = stop_reason_name(in.reason);
  extras.exit_code = exit_code;
  extras.events_lost = log.lost();
  std::cerr << summary_report(exec, extras);
  notifier.status(summary_line(exec));
  if (!options.summary_json.empty()) {
    std::ofstream out(options.summary_json);
    out << summary_json(exec, extras);
    if (!out) {
      std::cerr << "rig: cannot write " << options.summary_json << "\n";
      exit_code = 1;
    }
  }
  if (!message.empty()) std::cerr << "rig: error: " << message << "\n";
  return exit_code;
}

}  // namespace rig
