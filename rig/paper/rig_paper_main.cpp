// rig-paper: runs the paper's validation cases and writes their CSV (columns: paper_runs.h).
//   rig-paper quarter-car|pendulums [--h S] [--t-end S] [--method dae|spring-reference]
//             [--csv FILE]
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "rig/paper/paper_runs.h"

int main(int argc, char** argv) {
  CLI::App app{"rig-paper: the paper's validation cases (quarter car, coupled pendulums)"};
  std::string which;
  double h = 1e-3;
  double t_end = -1;
  std::string method = "dae";
  std::string csv_path;
  app.add_option("case", which, "quarter-car | pendulums")
      ->required()
      ->check(CLI::IsMember({"quarter-car", "pendulums"}));
  app.add_option("--h", h, "step size [s] (the reference's output interval)")
      ->check(CLI::PositiveNumber);
  app.add_option("--t-end", t_end, "end time [s] (default: 20 quarter car, 5 pendulums)");
  app.add_option("--method", method, "pendulums: dae | spring-reference (CVODE)")
      ->check(CLI::IsMember({"dae", "spring-reference"}));
  app.add_option("--csv", csv_path, "write the CSV here (default: standard output)");
  CLI11_PARSE(app, argc, argv);

  if (which == "quarter-car" && method != "dae") {
    std::cerr << "rig-paper: --method spring-reference applies to pendulums only\n";
    return 2;
  }
  if (t_end <= 0) t_end = which == "quarter-car" ? 20.0 : 5.0;

  std::ofstream file;
  std::ostream* out = &std::cout;
  if (!csv_path.empty()) {
    file.open(csv_path);
    if (!file) {
      std::cerr << "rig-paper: cannot write " << csv_path << "\n";
      return 1;
    }
    out = &file;
  }
  try {
    if (which == "quarter-car") {
      rig::paper::write_csv(*out, rig::paper::run_quarter_car(h, t_end));
    } else if (method == "dae") {
      rig::paper::write_csv(*out, rig::paper::run_pendulums_dae(h, t_end));
    } else {
      rig::paper::write_csv(*out, rig::paper::run_pendulums_spring(h, t_end));
    }
  } catch (const std::exception& e) {
    std::cerr << "rig-paper: " << e.what() << "\n";
    return 1;
  }
  out->flush();
  return out->good() ? 0 : 1;
}
