// TMeasy tire evaluation cost: the full evaluate() (eq. 24/26 with all partials), and the
// steady-state forces alone (eqs. 14-17).
#include <benchmark/benchmark.h>

#include "model/tire/tmeasy_dual_law.h"

namespace {

using rig::model::tire::legacy::TireDeflection;
using rig::model::tire::legacy::TireInput;
using rig::model::tire::legacy::TireOutput;
using rig::model::tire::legacy::TmeasyTire;

TireInput cornering_input() {
  TireInput in;
  in.long_speed_mps = 20.0;
  in.lat_speed_mps = -0.6;
  in.spin_radps = 68.0;
  in.rolling_radius_m = 0.3;
  in.load_n = 4100.0;
  in.friction = 1.0;
  return in;
}

void BM_TireEvaluate(benchmark::State& state) {
  const TmeasyTire tire;
  TireInput in = cornering_input();
  TireDeflection d{0.002, 0.003};
  TireOutput out;
  for (auto _ : state) {
    benchmark::DoNotOptimize(in);
    tire.evaluate(in, d, out);
    benchmark::DoNotOptimize(out);
    d.long_m += 1e-12;  // keep the call from being hoisted
  }
}
BENCHMARK(BM_TireEvaluate);

void BM_TireSteadyState(benchmark::State& state) {
  const TmeasyTire tire;
  TireInput in = cornering_input();
  for (auto _ : state) {
    benchmark::DoNotOptimize(in);
    benchmark::DoNotOptimize(tire.steady_state(in));
  }
}
BENCHMARK(BM_TireSteadyState);

}  // namespace

BENCHMARK_MAIN();
