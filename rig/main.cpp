/// @file
/// `rig`: command line. Exit codes: 0 ok, 2 bad usage or configuration, 1 runtime failure.

#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "io/config/config_error.h"
#include "rig/run.h"

namespace {

int check(const std::string& file) {
  try {
    const rig::RigConfig config = rig::load_config(file);
    rig::RunOptions options;
    options.config_file = file;
    try {
      (void)rig::make_io(config, options);  // loads DBC and mapping files, opens CAN
    } catch (const rig::io::config::ConfigError&) {
      throw;
    } catch (const std::exception& e) {
      std::cout << "note: " << e.what()
                << " (not available on this machine; not a configuration error)\n";
    }
    std::cout << file << ": OK\n";
    return 0;
  } catch (const rig::io::config::ConfigError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rig: a hard-real-time hardware-in-the-loop vehicle simulator"};
  app.set_version_flag("--version", std::string("rig ") + RIG_VERSION);
  app.require_subcommand(1);

  rig::RunOptions run;
  std::string stall;
  auto* run_cmd = app.add_subcommand("run", "run the simulator loop");
  run_cmd->add_option("--config", run.config_file, "configuration file (TOML)")->required();
  run_cmd
      ->add_option("--duration", run.duration_s,
                   "stop after S seconds (default: [rig] duration_s or forever)")
      ->check(CLI::PositiveNumber);
  run_cmd->add_flag("--offline", run.offline, "no sleeping, as fast as possible, deterministic");
  run_cmd->add_option("--can", run.can, "CAN interface, or 'none'");
  run_cmd->add_option("--lcm-url", run.lcm_url, "LCM URL, or 'none'");
  run_cmd->add_option("--lcm-log", run.lcm_log, "write an LCM event log to FILE");
  run_cmd->add_option("--overrun-log", run.overrun_log,
                      "JSON-lines log of deadline misses and events");
  run_cmd->add_option("--summary-json", run.summary_json, "write the summary as JSON to FILE");
  run_cmd->add_option("--cpu", run.cpu, "pin the loop thread to CPU N")->check(CLI::Range(0, 1023));
  run_cmd->add_option("--priority", run.priority, "SCHED_FIFO priority")->check(CLI::Range(1, 99));
  run_cmd->add_flag("--require-rt", run.require_rt, "fail if SCHED_FIFO or mlockall is refused");
  run_cmd->add_option("--inject-stall", stall, "test hook: CYCLE:MS")->group("");

  std::string check_file;
  auto* check_cmd = app.add_subcommand("check", "validate a configuration without running");
  check_cmd->add_option("FILE", check_file, "configuration file")->required();

  try {
    app.parse(argc, argv);
    if (!stall.empty()) {
      const auto colon = stall.find(':');
      if (colon == std::string::npos)
        throw CLI::ValidationError("--inject-stall", "expected CYCLE:MS");
      run.stall_cycle = std::stoull(stall.substr(0, colon));
      run.stall_ms = std::stoll(stall.substr(colon + 1));
    }
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const std::exception& e) {
    std::cerr << "rig: bad --inject-stall: " << e.what() << "\n";
    return 2;
  }
  if (*check_cmd) return check(check_file);
  return rig::run(run);
}
