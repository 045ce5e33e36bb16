// The cost probe of the van's step with leaf-sprung or plain rear axle (van_leaf_steps.h) for
// callgrind: N steps inside measured_steps(),
//   valgrind --tool=callgrind --callgrind-out-file=/dev/null
//       --toggle-collect='measured_steps*' build/bin/leaf_axle_cost leaf|plain N
// (the difference of N = 1000 and N = 0 is the steps' instructions).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "model/vehicle/vehicle_model.h"
#include "tests/bench/leaf_spring/van_leaf_steps.h"

/// The measured region (not inlined, so that callgrind can toggle on it).
__attribute__((noinline)) void measured_steps(rig::model::vehicle::VehicleModel& m,
                                              rig::model::Signals& s, int n) {
  for (int k = 0; k < n; ++k) {
    rig::test::van_inputs(m.time_s(), s);
    (void)m.step(s);
  }
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: leaf_axle_cost leaf|plain STEPS\n");
    return 2;
  }
  const bool leaf = std::string(argv[1]) == "leaf";
  rig::model::vehicle::VehicleModel m(rig::test::van_params(leaf), 1e-3);
  rig::model::Signals s = rig::test::all_driver_inputs();
  m.set_forward_speed(rig::test::kVanSpeedMps);
  for (int k = 0; k < rig::test::kVanWarmSteps; ++k) {
    rig::test::van_inputs(m.time_s(), s);
    (void)m.step(s);
  }
  measured_steps(m, s, std::atoi(argv[2]));
  std::printf("t = %.3f s, v = %.2f m/s\n", m.time_s(), m.state().framework_z(0));
  return 0;
}
