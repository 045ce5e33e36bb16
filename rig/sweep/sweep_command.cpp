#include "rig/sweep/sweep_command.h"

#include <iostream>
#include <set>
#include <stdexcept>

#include "io/config/config_error.h"
#include "rig/config.h"
#include "rig/rt/thread_setup.h"
#include "rig/sweep/sweep_collect.h"
#include "rig/sweep/sweep_local.h"
#include "rig/sweep/sweep_slurm.h"
#include "rig/sweep/sweep_task.h"

namespace rig::sweep {
namespace {

/// A bad sweep found before any run (exit 2).
class SweepError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::string describe(const SweepRun& r) {
  std::string d = r.maneuver;
  if (!r.road.empty()) d += ", road " + r.road;
  for (const auto& [k, v] : r.vary) d.append(", ").append(k).append("=").append(v);
  if (r.seed) d += ", seed " + std::to_string(*r.seed);
  return d;
}

/// Loads the configuration of every run that brings an axis value not loaded before (the first
/// run, then each new maneuver, road, value and seed: the sum of the axes' lengths, not their
/// product), as rig run would: a bad key path or value is exit 2 before anything runs.
void check_values(const SweepSpec& spec, const std::vector<SweepRun>& runs) {
  std::set<std::string> seen;
  for (const SweepRun& r : runs) {
    std::vector<std::string> values{"m:" + r.config.string(), "r:" + r.road,
                                    "s:" + (r.seed ? std::to_string(*r.seed) : "")};
    for (const auto& [k, v] : r.vary)
      values.push_back(std::string("v:").append(k).append("=").append(v));
    bool fresh = false;
    for (const auto& v : values) fresh = seen.insert(v).second || fresh;
    if (!fresh) continue;
    try {
      const RigConfig c = load_config(r.config, io::config::Overrides(r.sets));
      if (spec.duration_s && *spec.duration_s < c.rig.period_s)
        throw SweepError("duration_s " + std::to_string(*spec.duration_s) +
                         " s is shorter than one period");
    } catch (const std::exception& e) {
      throw SweepError("run " + r.id + " (" + describe(r) + "): " + e.what());
    }
  }
}

}  // namespace

std::size_t check_sweep_spec(const std::filesystem::path& spec_file) {
  const SweepSpec spec = load_sweep_spec(spec_file);
  const std::vector<SweepRun> runs = expand(spec);
  check_values(spec, runs);
  return runs.size();
}

namespace {

std::filesystem::path out_dir(const SweepOptions& o, const std::string& name) {
  return o.out.empty() ? std::filesystem::path("out") / ("sweep-" + name)
                       : std::filesystem::path(o.out);
}

/// A fresh DIR (an earlier sweep's results must not mix with this one's).
void prepare_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir / "plan.json", ec) || std::filesystem::exists(dir / "runs", ec))
    throw SweepError(dir.string() + " holds an earlier sweep; remove it or give another --out");
  std::filesystem::create_directories(dir / "runs", ec);
  if (ec) throw SweepError(dir.string() + ": " + ec.message());
}

int report(const Campaign& c, bool fail_on_kpi) {
  std::cerr << "rig sweep: " << c.runs << " runs: " << c.ok << " ok, " << c.kpi_failed
            << " with a KPI failed, " << c.failed << " failed or missing; " << c.csv.string()
            << "\n";
  return sweep_exit_code(c, fail_on_kpi);
}

int sweep(const SweepOptions& o) {
  const SweepSpec spec = load_sweep_spec(o.spec);
  const std::filesystem::path dir = out_dir(o, spec.name);
  const Plan plan = make_plan(spec, dir, o.keep_logs);
  check_values(spec, plan.runs);
  prepare_dir(plan.dir);
  write_plan(plan);
  if (o.slurm) {
    (void)run_slurm(plan, o.workers);
  } else {
    const int workers = o.workers > 0 ? o.workers : rt::cpu_count();
    std::cerr << "rig sweep: " << plan.runs.size() << " runs of " << spec.name << " on " << workers
              << " workers into " << plan.dir.string() << "\n";
    (void)run_local(plan, workers);
  }
  return report(collect(plan, !o.no_plots), o.fail_on_kpi);
}

}  // namespace

int sweep_command(const SweepOptions& o) {
  try {
    if (o.task) {
      const Plan plan = read_plan(o.out);
      if (*o.task < 0 || static_cast<std::size_t>(*o.task) >= slurm_tasks(plan))
        throw SweepError("--task " + std::to_string(*o.task) + ": the plan has " +
                         std::to_string(slurm_tasks(plan)) + " tasks");
      return run_slurm_task(plan, static_cast<std::size_t>(*o.task));
    }
    if (o.collect) {
      const Plan plan = read_plan(o.out.empty() ? out_dir(o, load_sweep_spec(o.spec).name)
                                                : std::filesystem::path(o.out));
      return report(collect(plan, !o.no_plots), o.fail_on_kpi);
    }
    return sweep(o);
  } catch (const io::config::ConfigError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const SweepError& e) {
    std::cerr << "rig sweep: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rig sweep: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace rig::sweep
