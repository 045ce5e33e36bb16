#include "rig/sweep/sweep_collect.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "rig/kpi/junit.h"
#include "rig/sweep/process.h"
#include "rig/sweep/sweep_task.h"

namespace rig::sweep {
namespace {

using nlohmann::json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool read_json(const std::filesystem::path& file, json& out) {
  std::ifstream in(file);
  if (!in) return false;
  try {
    out = json::parse(in);
    return true;
  } catch (const json::exception&) {
    return false;
  }
}

double number(const json& j, const char* key) {
  return j.contains(key) && j.at(key).is_number() ? j.at(key).get<double>() : kNaN;
}

std::vector<kpi::KpiResult> kpis_of(const json& summary) {
  std::vector<kpi::KpiResult> out;
  if (!summary.contains("kpis")) return out;
  for (const auto& k : summary.at("kpis")) {
    kpi::KpiResult r;
    r.name = k.value("name", "");
    r.unit = k.value("unit", "");
    r.value = number(k, "value");
    const json& l = k.at("limits");
    if (l.at("min").is_number()) r.min = l.at("min").get<double>();
    if (l.at("max").is_number()) r.max = l.at("max").get<double>();
    r.passed = k.value("passed", false);
    out.push_back(std::move(r));
  }
  return out;
}

std::string last_line(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty() && line.rfind("  ", 0) != 0) last = line;  // not the summary's body
  return last.substr(0, 300);
}

std::string status_of(int code, const std::vector<kpi::KpiResult>& kpis) {
  switch (code) {
    case -1:
      return "missing";
    case 0:
      for (const auto& k : kpis)
        if (!k.passed) return "kpi_failed";
      return "ok";
    case 1:
      return "failed";
    case 2:
      return "bad_config";
    case 3:
      return "output_lost";
    default:
      return code >= 128 ? "killed" : "failed";
  }
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (const char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string csv_number(double v) {
  if (!std::isfinite(v)) return "";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

/// A TOML value as a cell: a string without its quotes.
std::string cell_of_value(const std::string& toml) {
  if (toml.size() >= 2 && toml.front() == '"' && toml.back() == '"')
    return toml.substr(1, toml.size() - 2);
  return toml;
}

/// The KPI names over all runs, in plan order.
std::vector<std::string> kpi_columns(const std::vector<RunResult>& results) {
  std::vector<std::string> names;
  for (const auto& r : results)
    for (const auto& k : r.kpis)
      if (std::find(names.begin(), names.end(), k.name) == names.end()) names.push_back(k.name);
  return names;
}

void write_csv(const Plan& plan, const std::vector<RunResult>& results,
               const std::filesystem::path& file) {
  std::ofstream out(file);
  const std::vector<std::string> kpis = kpi_columns(results);
  out << "id,maneuver,road,seed";
  for (const auto& k : plan.vary_keys) out << "," << csv_field(k);
  out << ",status,exit_code,stop_reason,sim_time_s,wall_time_s,kpis_failed,error";
  for (const auto& k : kpis) out << "," << csv_field(k) << "," << csv_field(k + ".passed");
  out << "\n";
  for (std::size_t i = 0; i < plan.runs.size(); ++i) {
    const SweepRun& run = plan.runs[i];
    const RunResult& r = results[i];
    out << run.id << "," << csv_field(run.maneuver) << "," << csv_field(run.road) << ","
        << (run.seed ? std::to_string(*run.seed) : "");
    for (const auto& [key, value] : run.vary) out << "," << csv_field(cell_of_value(value));
    int failed = 0;
    for (const auto& k : r.kpis) failed += k.passed ? 0 : 1;
    out << "," << r.status << "," << (r.exit_code >= 0 ? std::to_string(r.exit_code) : "") << ","
        << csv_field(r.stop_reason) << "," << csv_number(r.sim_time_s) << ","
        << csv_number(r.wall_time_s) << "," << failed << "," << csv_field(r.error);
    for (const auto& name : kpis) {
      const auto it =
          std::find_if(r.kpis.begin(), r.kpis.end(), [&](const auto& k) { return k.name == name; });
      if (it == r.kpis.end()) {
        out << ",,";
        continue;
      }
      out << "," << csv_number(it->value) << ","
          << (std::isfinite(it->value) ? (it->passed ? "1" : "0") : "");
    }
    out << "\n";
  }
  if (!out.flush()) throw std::runtime_error(file.string() + ": cannot write the campaign");
}

kpi::JunitSuite suite_of(const Plan& plan, const SweepRun& run, const RunResult& r) {
  kpi::JunitSuite s;
  s.name = run.id;
  s.package = plan.name;
  s.timestamp = r.started.empty() ? kpi::junit_timestamp(0) : r.started;
  s.hostname = kpi::host_name();
  s.time_s = std::isfinite(r.wall_time_s) ? r.wall_time_s : 0.0;
  s.properties = {{"maneuver", run.maneuver}};
  if (!run.road.empty()) s.properties.emplace_back("road", run.road);
  if (run.seed) s.properties.emplace_back("seed", std::to_string(*run.seed));
  for (const auto& set : run.sets) s.properties.emplace_back("set", set);
  s.properties.emplace_back("status", r.status);
  s.kpis = r.kpis;
  if (r.status != "ok" && r.status != "kpi_failed") {
    s.run_error = r.status + (r.error.empty() ? "" : ": " + r.error);
    if (s.kpis.empty()) s.kpis.push_back({"run", "", kNaN, std::nullopt, std::nullopt, false});
  }
  return s;
}

void make_plots(const Plan& plan) {
  const auto scripts = scripts_dir(plan.rig);
  if (scripts.empty()) {
    std::cerr
        << "rig sweep: warning: no summary plots: scripts/plot not found (set RIG_SCRIPTS_DIR)\n";
    return;
  }
  std::string error;
  const pid_t pid = spawn({(scripts / "plot").string(), "campaign", plan.dir.string()},
                          plan.dir / "plots.log", error);
  if (pid < 0 || wait_for(pid) != 0)
    std::cerr << "rig sweep: warning: the summary plots failed ("
              << (plan.dir / "plots.log").string() << ")\n";
}

}  // namespace

RunResult read_result(const Plan& plan, const SweepRun& run) {
  RunResult r;
  r.sim_time_s = r.wall_time_s = kNaN;
  const auto dir = run_dir(plan, run);
  json status, summary;
  if (read_json(dir / "status.json", status)) {
    r.exit_code = status.value("exit_code", -1);
    r.wall_time_s = number(status, "wall_time_s");
    r.started = status.value("started", "");
  }
  if (read_json(dir / "summary.json", summary)) {
    r.kpis = kpis_of(summary);
    r.stop_reason = summary.value("stop_reason", "");
    r.sim_time_s = number(summary, "sim_time_s");
  }
  r.status = status_of(r.exit_code, r.kpis);
  if (r.exit_code == 0 && r.stop_reason == "signal") r.status = "interrupted";
  if (r.status != "ok" && r.status != "kpi_failed" && r.status != "missing")
    r.error = last_line(dir / "rig.log");
  return r;
}

Campaign collect(const Plan& plan, bool plots) {
  std::vector<RunResult> results;
  std::vector<kpi::JunitSuite> suites;
  Campaign c;
  for (const auto& run : plan.runs) {
    results.push_back(read_result(plan, run));
    const RunResult& r = results.back();
    ++c.runs;
    (r.status == "ok" ? c.ok : r.status == "kpi_failed" ? c.kpi_failed : c.failed) += 1;
    suites.push_back(suite_of(plan, run, r));
  }
  c.csv = plan.dir / "campaign.csv";
  write_csv(plan, results, c.csv);
  std::ofstream(plan.dir / "junit.xml") << kpi::junit_xml(suites, plan.name);
  if (plots) make_plots(plan);
  return c;
}

int sweep_exit_code(const Campaign& c, bool fail_on_kpi) {
  if (c.failed > 0) return 1;
  return fail_on_kpi && c.kpi_failed > 0 ? 3 : 0;
}

}  // namespace rig::sweep
