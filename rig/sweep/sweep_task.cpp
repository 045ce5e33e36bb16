#include "rig/sweep/sweep_task.h"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>

#include "rig/kpi/junit.h"
#include "rig/sweep/process.h"

namespace rig::sweep {
namespace {

std::string host() {
  char buf[256] = {};
  return ::gethostname(buf, sizeof buf - 1) == 0 ? buf : "";
}

/// Runs argv, its output appended to `log`; its exit code, or 1 if it did not start.
int run_to_end(const std::vector<std::string>& argv, const std::filesystem::path& log) {
  std::string error;
  const pid_t pid = spawn(argv, log, error);
  if (pid < 0) {
    std::ofstream(log, std::ios::app) << "rig sweep: cannot start " << error << "\n";
    return 1;
  }
  return wait_for(pid);
}

void write_status(const std::filesystem::path& dir, const SweepRun& run, int code, double wall_s,
                  const std::string& started) {
  const nlohmann::json j{{"id", run.id},
                         {"exit_code", code},
                         {"wall_time_s", wall_s},
                         {"started", started},
                         {"host", host()}};
  const auto tmp = dir / "status.json.tmp";
  std::ofstream(tmp) << j.dump() << "\n";
  std::error_code ec;
  std::filesystem::rename(tmp, dir / "status.json", ec);
}

/// --keep-logs: the run's CSVs and figures (what the demo makes), their output in rig.log.
void keep_logs(const Plan& plan, const std::filesystem::path& dir) {
  const auto log = dir / "rig.log";
  const auto log2csv = plan.rig.parent_path() / "rig-log2csv";
  if (run_to_end({log2csv.string(), (dir / "run.lcm").string(), (dir / "csv").string()}, log) != 0)
    return;
  const auto scripts = scripts_dir(plan.rig);
  if (scripts.empty()) return;
  (void)run_to_end(
      {(scripts / "plot").string(), "log", (dir / "csv").string(), (dir / "figures").string()},
      log);
}

}  // namespace

std::filesystem::path scripts_dir(const std::filesystem::path& rig_exe) {
  std::vector<std::filesystem::path> candidates;
  if (const char* env = std::getenv("RIG_SCRIPTS_DIR")) candidates.emplace_back(env);
  candidates.push_back(rig_exe.parent_path() / ".." / "share" / "rig" / "scripts");
#ifdef RIG_SOURCE_DIR
  candidates.emplace_back(RIG_SOURCE_DIR "/scripts");
#endif
  for (const auto& c : candidates) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(c / "plot", ec)) return c.lexically_normal();
  }
  return {};
}

int run_task(const Plan& plan, std::size_t index) {
  const SweepRun& run = plan.runs.at(index);
  const auto dir = run_dir(plan, run);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const auto start = std::chrono::steady_clock::now();
  const std::string started =
      kpi::junit_timestamp(std::chrono::duration_cast<std::chrono::nanoseconds>(
                               std::chrono::system_clock::now().time_since_epoch())
                               .count());
  const int code = run_to_end(run_command(plan, run), dir / "rig.log");
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (plan.keep_logs) keep_logs(plan, dir);
  write_status(dir, run, code, wall_s, started);
  return code;
}

}  // namespace rig::sweep
