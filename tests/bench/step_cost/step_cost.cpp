// The step-cost probe of scripts/step-instructions: N model steps in a steady cornering + driving
// state (every force law active) inside measured_steps(), so that
// `valgrind --tool=callgrind --toggle-collect=measured_steps*` counts exactly those instructions.
//   rig_step_cost vehicle FILE | combination FILE  [STEPS=1000]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/config/vehicle_file.h"
#include "model/combination/combination.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/bench_inputs.h"
#include "tests/support/combination_files.h"

namespace {

using rig::model::Signal;
using rig::model::Signals;

}  // namespace

/// The measured region (not inlined, so that callgrind can toggle on it).
__attribute__((noinline)) void measured_steps(rig::model::SteppedModel& m, Signals& s, int n) {
  for (int k = 0; k < n; ++k) (void)m.step(s);
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: rig_step_cost vehicle|combination FILE [STEPS]\n");
    return 2;
  }
  const std::string kind = argv[1];
  const int n = argc > 3 ? std::atoi(argv[3]) : 1000;
  Signals s = rig::test::cornering_inputs();
  auto run = [&](auto& m) {
    m.set_forward_speed(15);
    for (int k = 0; k < 2000; ++k) (void)m.step(s);  // into a steady turn
    measured_steps(m, s, n);
    std::printf("t = %.3f s\n", m.time_s());
  };
  if (kind == "vehicle") {
    rig::model::vehicle::VehicleModel m(rig::io::config::load_vehicle_file(argv[2]), 1e-3);
    run(m);
  } else {
    rig::model::combination::Combination m(rig::test::load_combination(argv[2]), 1e-3);
    run(m);
  }
  return 0;
}
