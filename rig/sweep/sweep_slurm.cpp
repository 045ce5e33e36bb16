#include "rig/sweep/sweep_slurm.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "rig/signals.h"
#include "rig/sweep/process.h"
#include "rig/sweep/sweep_task.h"

namespace rig::sweep {
namespace {

/// A shell word: single quotes, a quote inside as '\''.
std::string sh(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string read_all(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Runs a Slurm command to its end; its output (stdout and stderr) in `out`.
int slurm_command(const std::vector<std::string>& argv, const std::filesystem::path& log,
                  std::string& out) {
  std::error_code ec;
  std::filesystem::remove(log, ec);
  std::string error;
  // the Slurm tools are found on PATH
  std::vector<std::string> a = {"/usr/bin/env"};
  a.insert(a.end(), argv.begin(), argv.end());
  const pid_t pid = spawn(a, log, error);
  if (pid < 0) throw std::runtime_error(error);
  const int code = wait_for(pid);
  out = read_all(log);
  return code;
}

/// Runs whose status.json exists.
std::size_t runs_done(const Plan& plan) {
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& r : plan.runs)
    n += std::filesystem::exists(run_dir(plan, r) / "status.json", ec);
  return n;
}

/// True while squeue lists a task of the job.
bool job_listed(const Plan& plan, const std::string& job) {
  std::string out;
  const int code = slurm_command({"squeue", "-h", "-j", job, "-o", "%i"},
                                 plan.dir / "slurm" / "squeue.out", out);
  if (code != 0) {
    if (out.find("Invalid job id") != std::string::npos) return false;  // purged: it ended
    throw std::runtime_error("squeue failed (exit " + std::to_string(code) + "): " + out);
  }
  return out.find_first_not_of(" \n") != std::string::npos;
}

}  // namespace

std::size_t slurm_tasks(const Plan& plan) {
  const auto k = static_cast<std::size_t>(std::max(1, plan.slurm.runs_per_task));
  return (plan.runs.size() + k - 1) / k;
}

std::string sbatch_script(const Plan& plan, int max_parallel) {
  std::string s = "#!/bin/sh\n";
  s += "#SBATCH --job-name=" + ("rig-sweep-" + plan.name) + "\n";
  s += "#SBATCH --array=0-" + std::to_string(slurm_tasks(plan) - 1) +
       (max_parallel > 0 ? "%" + std::to_string(max_parallel) : "") + "\n";
  s += "#SBATCH --output=" + (plan.dir / "slurm" / "task-%a.out").string() + "\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(plan.slurm.cpus_per_task) + "\n";
  if (!plan.slurm.partition.empty()) s += "#SBATCH --partition=" + plan.slurm.partition + "\n";
  if (!plan.slurm.time.empty()) s += "#SBATCH --time=" + plan.slurm.time + "\n";
  for (const auto& o : plan.slurm.options) s += "#SBATCH " + o + "\n";
  s += "# rig sweep: array task i runs runs i*" + std::to_string(plan.slurm.runs_per_task) +
       " .. of " + (plan.dir / "plan.json").string() + " (" + std::to_string(plan.runs.size()) +
       " runs); rig sweep --collect gathers them\n";
  s += "exec " + sh(plan.rig.string()) + " sweep " + sh(plan.spec.string()) + " --out " +
       sh(plan.dir.string()) + " --task \"$SLURM_ARRAY_TASK_ID\"\n";
  return s;
}

std::string run_slurm(const Plan& plan, int max_parallel) {
  std::filesystem::create_directories(plan.dir / "slurm");
  const auto script = plan.dir / "sweep.sbatch";
  std::ofstream(script) << sbatch_script(plan, max_parallel);
  std::string out;
  const int code = slurm_command({"sbatch", "--parsable", script.string()},
                                 plan.dir / "slurm" / "sbatch.out", out);
  std::string job = out.substr(0, out.find_first_not_of("0123456789"));
  if (code != 0 || job.empty())
    throw std::runtime_error("sbatch failed (exit " + std::to_string(code) + "): " + out);
  std::cerr << "rig sweep: submitted job " << job << " (" << slurm_tasks(plan) << " array tasks, "
            << plan.runs.size() << " runs); waiting for it to end (rig sweep " << plan.spec.string()
            << " --out " << plan.dir.string() << " --collect gathers the results later)\n";
  const auto start = std::chrono::steady_clock::now();
  auto last = start;
  bool cancelled = false;
  while (job_listed(plan, job)) {
    if (!cancelled && stop_signal() != 0) {
      cancelled = true;
      std::cerr << "rig sweep: stopping: scancel " << job << "\n";
      (void)slurm_command({"scancel", job}, plan.dir / "slurm" / "scancel.out", out);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    if (std::chrono::steady_clock::now() - last > std::chrono::seconds(10)) {
      last = std::chrono::steady_clock::now();
      std::fprintf(stderr, "rig sweep: job %s: %zu/%zu runs done, %.0f s\n", job.c_str(),
                   runs_done(plan), plan.runs.size(),
                   std::chrono::duration<double>(last - start).count());
    }
  }
  return job;
}

int run_slurm_task(const Plan& plan, std::size_t task) {
  const auto k = static_cast<std::size_t>(std::max(1, plan.slurm.runs_per_task));
  int worst = 0;
  for (std::size_t i = task * k; i < plan.runs.size() && i < (task + 1) * k; ++i)
    worst = std::max(worst, run_task(plan, i));
  return worst;
}

}  // namespace rig::sweep
