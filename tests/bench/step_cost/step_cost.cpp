// The step-cost probe of scripts/step-instructions: N model steps in a steady cornering + driving
// state (every force law active) inside measured_steps(), so that
// `valgrind --tool=callgrind --toggle-collect=measured_steps*` counts exactly those instructions.
//   rig_step_cost vehicle FILE | combination FILE  [STEPS=1000]
//   rig_step_cost straight FILE [CRG]   the road's cost (issue 16): straight at 5 m/s over the
//                                       OpenCRG file CRG (the Belgian block), or without it the
//                                       same on the plane; 200 steps, then 1000 measured
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/config/crg_file.h"
#include "io/config/vehicle_file.h"
#include "model/combination/combination.h"
#include "model/road/crg_surface.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/support/bench_inputs.h"
#include "tests/support/combination_files.h"

namespace {

using rig::model::Signals;

}  // namespace

/// The measured region (not inlined, so that callgrind can toggle on it).
__attribute__((noinline)) void measured_steps(rig::model::SteppedModel& m, Signals& s, int n) {
  for (int k = 0; k < n; ++k) (void)m.step(s);
}

/// The sedan straight over the CRG file `crg` (nullptr: on the plane).
int straight(const char* vehicle, const char* crg) {
  rig::model::vehicle::VehicleParams p = rig::io::config::load_vehicle_file(vehicle);
  if (crg != nullptr) {
    rig::model::road::Placement at;
    at.given = true;
    at.x_m = rig::test::kRoadBenchBlockX;
    p.road.surface =
        std::make_shared<rig::model::road::CrgSurface>(rig::io::config::load_crg_file(crg), at);
  }
  rig::model::vehicle::VehicleModel m(p, 1e-3);
  Signals s = rig::test::straight_inputs();
  m.set_forward_speed(rig::test::kRoadBenchSpeedMps);
  for (int k = 0; k < rig::test::kRoadBenchWarmSteps; ++k) (void)m.step(s);
  measured_steps(m, s, rig::test::kRoadBenchSteps);
  std::printf("t = %.3f s, x = %.3f m\n", m.time_s(), m.state().framework_y(0));
  return 0;
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: rig_step_cost vehicle|combination FILE [STEPS]\n"
                 "       rig_step_cost straight FILE [CRG]\n");
    return 2;
  }
  const std::string kind = argv[1];
  if (kind == "straight") return straight(argv[2], argc > 3 ? argv[3] : nullptr);
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
