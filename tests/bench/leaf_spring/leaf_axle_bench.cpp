// The van's step with its leaf-sprung rear axle (model/vehicle/leaf_axle.h) against the same
// axle on plain springs of the same rates (van_leaf_steps.h): the cost of the five-link leaves
// in the vehicle (model/vehicle/leaf_spring/RESULTS.md; the paper, sec. 2.3: +85 % run time).
#include <benchmark/benchmark.h>

#include "model/vehicle/vehicle_model.h"
#include "tests/bench/leaf_spring/van_leaf_steps.h"

namespace {

void van_step(benchmark::State& st, bool leaf) {
  rig::model::vehicle::VehicleModel m(rig::test::van_params(leaf), 1e-3);
  rig::model::Signals s = rig::test::all_driver_inputs();
  m.set_forward_speed(rig::test::kVanSpeedMps);
  for (int k = 0; k < rig::test::kVanWarmSteps; ++k) {
    rig::test::van_inputs(m.time_s(), s);
    (void)m.step(s);
  }
  for (auto _ : st) {
    rig::test::van_inputs(m.time_s(), s);
    benchmark::DoNotOptimize(m.step(s));
    if (m.time_s() > 20.0) {  // stay in the cycle: back to speed
      st.PauseTiming();
      m.reset(0, 0, 0);
      m.set_forward_speed(rig::test::kVanSpeedMps);
      st.ResumeTiming();
    }
  }
}

void BM_VanStepLeafAxle(benchmark::State& st) { van_step(st, true); }
void BM_VanStepPlainSprings(benchmark::State& st) { van_step(st, false); }

}  // namespace

BENCHMARK(BM_VanStepLeafAxle)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_VanStepPlainSprings)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
