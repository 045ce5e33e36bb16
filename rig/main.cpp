/// @file
/// `rig`: command line. Exit codes: 0 ok, 2 bad usage or configuration, 1 runtime failure, 3 the
/// run ended as asked but an output lost data (a failed write: a full disk).

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/lcm/lcm_settings.h"
#include "rig/check.h"
#include "rig/road_sample.h"
#include "rig/rt/thread_setup.h"
#include "rig/run.h"
#include "rig/signals.h"
#include "rig/signals_command.h"
#include "rig/sweep/sweep_command.h"

namespace {

/// `rig check FILE... [--kind KIND]`: exit 0 if every file checks OK, else 2.
int check(const std::vector<std::string>& files, const std::string& kind_name) {
  const rig::FileKind* kind = kind_name.empty() ? nullptr : rig::find_file_kind(kind_name);
  int code = 0;
  for (const auto& file : files) {
    code = std::max(code, rig::check_file(file, kind, std::cout, std::cerr));
  }
  return code;
}

/// --lcm-url: "none" or a well-formed LCM URL (io/lcm/lcm_settings.h, as [lcm] url).
CLI::Validator lcm_url_validator() {
  return CLI::Validator(
      [](const std::string& url) {
        return url == "none" ? std::string() : rig::io::lcm::lcm_url_problem(url);
      },
      "URL");
}

/// --cpu: a CPU this machine has (as [rig] cpu).
CLI::Validator cpu_validator() {
  return CLI::Validator(
      [](const std::string& text) {
        const int n = rig::rt::cpu_count();
        int cpu = -1;
        if (!CLI::detail::lexical_cast(text, cpu) || cpu < 0 || cpu >= n)
          return "CPU " + text + " does not exist: this machine has " + std::to_string(n) +
                 " (0.." + std::to_string(n - 1) + ")";
        return std::string();
      },
      "CPU");
}

/// `rig run`'s options into `run` (and the test hook's text into `stall`).
void add_run(CLI::App& app, rig::RunOptions& run, std::string& stall) {
  auto* run_cmd = app.add_subcommand("run", "run the simulator loop");
  run_cmd->add_option("--config", run.config_file, "configuration file (TOML)")->required();
  run_cmd
      ->add_option("--set", run.sets,
                   "KEY=VALUE: set a configuration key before it is read, also of the vehicle "
                   "file (vehicle.chassis.mass_kg=1600; unit<k>. for a combination's units); "
                   "repeatable (docs/sweeps.md)")
      ->allow_extra_args(false);
  run_cmd->add_option("--junit", run.junit,
                      "write the KPIs as JUnit XML to FILE (one <testsuite>, one <testcase> per "
                      "KPI)");
  run_cmd->add_flag("--fail-on-kpi", run.fail_on_kpi,
                    "exit 3 if a KPI failed its limits (a run failure stays exit 1)");
  run_cmd->add_option("--duration", run.duration_s,
                      "stop after S seconds (default: [rig] duration_s or forever); finite, at "
                      "least one period");
  run_cmd->add_flag("--offline", run.offline, "no sleeping, as fast as possible, deterministic");
  run_cmd->add_option("--can", run.can, "CAN interface, or 'none'");
  run_cmd->add_option("--lcm-url", run.lcm_url, "LCM URL, or 'none'")->check(lcm_url_validator());
  run_cmd->add_option("--lcm-log", run.lcm_log, "write an LCM event log to FILE");
  run_cmd->add_option("--overrun-log", run.overrun_log,
                      "JSON-lines log of deadline misses and events");
  run_cmd->add_option("--summary-json", run.summary_json, "write the summary as JSON to FILE");
  run_cmd->add_option("--cpu", run.cpu, "pin the loop thread to CPU N")->check(cpu_validator());
  run_cmd->add_option("--priority", run.priority, "SCHED_FIFO priority")->check(CLI::Range(1, 99));
  run_cmd->add_flag("--require-rt", run.require_rt,
                    "fail if SCHED_FIFO, mlockall or the CPU pinning is refused");
  run_cmd->add_flag("--lockstep", run.lockstep,
                    "test mode: each cycle waits, up to 100 ms, for its CAN cycle frame (the "
                    "received messages with a cycle time <= the period) before stepping; a "
                    "timeout is counted and logged, the cycle runs on the held inputs; the wait "
                    "is not a deadline miss (docs/can.md, Lock-step)");
  run_cmd->add_option("--inject-stall", stall, "test hook: CYCLE:MS")->group("");
}

/// `rig check FILE... [--kind KIND]`.
const CLI::App* add_check(CLI::App& app, std::vector<std::string>& files, std::string& kind) {
  std::vector<std::string> kind_names;
  for (const auto& k : rig::file_kinds()) kind_names.emplace_back(k.name);
  auto* check_cmd = app.add_subcommand(
      "check",
      "validate files without running: run configurations, combinations, vehicles, "
      "CAN mappings, DBCs (the kind is recognised from the content)");
  check_cmd->add_option("FILE", files, "files to check")->required();
  check_cmd->add_option("--kind", kind, "check every FILE as this kind")
      ->check(CLI::IsMember(kind_names));
  return check_cmd;
}

/// `rig signals CONFIG [--json]`.
const CLI::App* add_signals(CLI::App& app, std::string& config, bool& json) {
  auto* signals_cmd = app.add_subcommand(
      "signals",
      "print the signal catalogue of a run configuration's model: name, unit, direction, min, "
      "max, aliases (docs/signals.md)");
  signals_cmd->add_option("CONFIG", config, "run configuration (TOML)")->required();
  signals_cmd->add_flag("--json", json,
                        "a JSON array of {name, unit, direction, min, max, aliases}");
  return signals_cmd;
}

/// `rig road sample --config FILE --xy POINTS.csv`.
const CLI::App* add_road(CLI::App& app, std::string& config, std::string& points) {
  auto* road_cmd = app.add_subcommand("road", "the road a run configuration gives its tires");
  road_cmd->require_subcommand(1);
  auto* sample_cmd = road_cmd->add_subcommand(
      "sample",
      "print x,y,z,nx,ny,nz,mu (height, upward normal, mu scale) at each point of POINTS.csv "
      "(header x,y, then one point per line)");
  sample_cmd->add_option("--config", config, "run configuration (TOML)")->required();
  sample_cmd->add_option("--xy", points, "CSV of points: header x,y")->required();
  return sample_cmd;
}

/// `rig sweep SPEC [--workers N] [--out DIR] [--slurm] ...`.
const CLI::App* add_sweep(CLI::App& app, rig::sweep::SweepOptions& o) {
  auto* cmd = app.add_subcommand(
      "sweep",
      "run a campaign: SPEC's matrix of runs (base or maneuvers, [[roads]], [[vary]] key/values, "
      "seeds) offline, locally or as a Slurm job array; DIR/runs/<id>/, DIR/campaign.csv, "
      "DIR/junit.xml, DIR/plots/ (docs/sweeps.md)");
  cmd->add_option("SPEC", o.spec, "sweep specification (TOML)")->required();
  cmd->add_option("--workers", o.workers,
                  "local worker processes (default: the CPUs); with --slurm the most array "
                  "tasks running at once (default: no limit)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--out", o.out, "output folder (default out/sweep-NAME); must not hold a sweep");
  cmd->add_flag("--slurm", o.slurm,
                "submit the runs as a Slurm job array (sbatch) and collect when it ends");
  cmd->add_flag("--keep-logs", o.keep_logs,
                "keep each run's LCM log, overrun log, CSVs and figures (else summary and KPIs)");
  cmd->add_flag("--fail-on-kpi", o.fail_on_kpi, "exit 3 if a run's KPI failed");
  cmd->add_flag("--no-plots", o.no_plots, "no summary plots");
  cmd->add_flag("--collect", o.collect, "only gather DIR's results again (campaign.csv, ...)");
  cmd->add_option("--task", o.task,
                  "run array task I of DIR's plan (what the sbatch script runs; needs --out)")
      ->needs(cmd->get_option("--out"));
  return cmd;
}

/// --inject-stall CYCLE:MS into `run`.
void parse_stall(const std::string& stall, rig::RunOptions& run) {
  if (stall.empty()) return;
  const auto colon = stall.find(':');
  if (colon == std::string::npos) throw CLI::ValidationError("--inject-stall", "expected CYCLE:MS");
  run.stall_cycle = std::stoull(stall.substr(0, colon));
  run.stall_ms = std::stoll(stall.substr(colon + 1));
}

}  // namespace

int main(int argc, char** argv) {
  rig::install_signal_handlers();  // before anything else (rig/signals.h)
  CLI::App app{"rig: a hard-real-time hardware-in-the-loop vehicle simulator"};
  app.set_version_flag("--version", std::string("rig ") + RIG_VERSION);
  app.require_subcommand(1);

  rig::RunOptions run;
  std::string stall;
  add_run(app, run, stall);
  std::vector<std::string> check_files;
  std::string check_kind;
  const CLI::App* check_cmd = add_check(app, check_files, check_kind);
  std::string signals_config;
  bool signals_json = false;
  const CLI::App* signals_cmd = add_signals(app, signals_config, signals_json);
  std::string road_config;
  std::string road_points;
  const CLI::App* road_sample_cmd = add_road(app, road_config, road_points);
  rig::sweep::SweepOptions sweep;
  const CLI::App* sweep_cmd = add_sweep(app, sweep);

  try {
    app.parse(argc, argv);
    parse_stall(stall, run);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const std::exception& e) {
    std::cerr << "rig: bad --inject-stall: " << e.what() << "\n";
    return 2;
  }
  if (*check_cmd) return check(check_files, check_kind);
  if (*signals_cmd) return rig::signals_command(signals_config, signals_json, std::cout, std::cerr);
  if (*road_sample_cmd)
    return rig::road_sample_command(road_config, road_points, std::cout, std::cerr);
  if (*sweep_cmd) return rig::sweep::sweep_command(sweep);
  return rig::run(run);
}
