#include "rig/sweep/sweep_plan.h"

#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "rig/sweep/process.h"

namespace rig::sweep {
namespace {

using nlohmann::json;

json run_json(const SweepRun& r) {
  json j{{"index", r.index},       {"id", r.id},     {"config", r.config.string()},
         {"maneuver", r.maneuver}, {"road", r.road}, {"set", r.sets}};
  j["seed"] = r.seed ? json(*r.seed) : json(nullptr);
  json vary = json::array();
  for (const auto& [k, v] : r.vary) vary.push_back({{"key", k}, {"value", v}});
  j["vary"] = vary;
  return j;
}

SweepRun run_of(const json& j) {
  SweepRun r;
  r.index = j.at("index").get<std::size_t>();
  r.id = j.at("id").get<std::string>();
  r.config = j.at("config").get<std::string>();
  r.maneuver = j.at("maneuver").get<std::string>();
  r.road = j.at("road").get<std::string>();
  if (!j.at("seed").is_null()) r.seed = j.at("seed").get<long long>();
  for (const auto& v : j.at("vary"))
    r.vary.emplace_back(v.at("key").get<std::string>(), v.at("value").get<std::string>());
  r.sets = j.at("set").get<std::vector<std::string>>();
  return r;
}

}  // namespace

std::filesystem::path run_dir(const Plan& plan, const SweepRun& run) {
  return plan.dir / "runs" / run.id;
}

Plan make_plan(const SweepSpec& spec, const std::filesystem::path& dir, bool keep_logs) {
  Plan p;
  p.name = spec.name;
  p.spec = spec.file;
  p.dir = std::filesystem::absolute(dir).lexically_normal();
  p.rig = self_exe();
  p.duration_s = spec.duration_s;
  p.keep_logs = keep_logs;
  for (const auto& v : spec.vary) p.vary_keys.push_back(v.key);
  p.runs = expand(spec);
  p.slurm = spec.slurm;
  return p;
}

void write_plan(const Plan& p) {
  json runs = json::array();
  for (const auto& r : p.runs) runs.push_back(run_json(r));
  json j{{"name", p.name},        {"spec", p.spec.string()},  {"dir", p.dir.string()},
         {"rig", p.rig.string()}, {"keep_logs", p.keep_logs}, {"vary_keys", p.vary_keys},
         {"runs", runs}};
  j["duration_s"] = p.duration_s ? json(*p.duration_s) : json(nullptr);
  j["slurm"] = {{"partition", p.slurm.partition},
                {"time", p.slurm.time},
                {"cpus_per_task", p.slurm.cpus_per_task},
                {"runs_per_task", p.slurm.runs_per_task},
                {"options", p.slurm.options}};
  const auto file = p.dir / "plan.json";
  std::ofstream out(file);
  out << j.dump(1) << "\n";
  if (!out.flush()) throw std::runtime_error(file.string() + ": cannot write the plan");
}

Plan read_plan(const std::filesystem::path& dir) {
  const auto file = dir / "plan.json";
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": no plan (is this a rig sweep --out DIR?)");
  try {
    const json j = json::parse(in);
    Plan p;
    p.name = j.at("name").get<std::string>();
    p.spec = j.at("spec").get<std::string>();
    p.dir = j.at("dir").get<std::string>();
    p.rig = j.at("rig").get<std::string>();
    p.keep_logs = j.at("keep_logs").get<bool>();
    p.vary_keys = j.at("vary_keys").get<std::vector<std::string>>();
    if (!j.at("duration_s").is_null()) p.duration_s = j.at("duration_s").get<double>();
    const json& s = j.at("slurm");
    p.slurm = {s.at("partition").get<std::string>(), s.at("time").get<std::string>(),
               s.at("cpus_per_task").get<int>(), s.at("runs_per_task").get<int>(),
               s.at("options").get<std::vector<std::string>>()};
    for (const auto& r : j.at("runs")) p.runs.push_back(run_of(r));
    return p;
  } catch (const json::exception& e) {
    throw std::runtime_error(file.string() + ": not a plan of rig sweep: " + e.what());
  }
}

std::vector<std::string> run_command(const Plan& plan, const SweepRun& run) {
  const auto dir = run_dir(plan, run);
  std::vector<std::string> a{plan.rig.string(),
                             "run",
                             "--config",
                             run.config.string(),
                             "--offline",
                             "--lcm-url",
                             "none",
                             "--can",
                             "none",
                             "--summary-json",
                             (dir / "summary.json").string(),
                             "--junit",
                             (dir / "junit.xml").string()};
  if (plan.duration_s) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", *plan.duration_s);
    a.insert(a.end(), {"--duration", text});
  }
  if (plan.keep_logs) {
    a.insert(a.end(), {"--lcm-log", (dir / "run.lcm").string(), "--overrun-log",
                       (dir / "overrun.jsonl").string()});
  }
  for (const auto& s : run.sets) a.insert(a.end(), {"--set", s});
  return a;
}

}  // namespace rig::sweep
