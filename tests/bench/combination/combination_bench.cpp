// One coupled step of the car + trailer and the tractor + semitrailer (issue 7): the DAE
// coupling (Newton on lambda, eqs. 45-50) serial and with the parallel begin_step, against the
// force-coupled big implicit matrix (eqs. 32-38); in a steady turn while driving, so that every
// force law and all joint rows are active.
#include <cmath>

#include <benchmark/benchmark.h>

#include "model/combination/combination.h"
#include "model/combination/force_coupled.h"
#include "rig/thread_begin_step_runner.h"
#include "tests/support/bench_inputs.h"
#include "tests/support/combination_files.h"

namespace {

using rig::model::Signal;
using rig::model::Signals;
using rig::model::combination::Combination;
using rig::model::combination::CombinationParams;
using rig::model::combination::ForceCoupledCombination;

using rig::test::kCarTrailer;
using rig::test::kTractorSemi;
using rig::test::kTractorSemi40t;

CombinationParams load(const char* file, bool parallel) {
  CombinationParams p = rig::test::load_combination(file);
  p.parallel = parallel;
  p.begin_step_runner = rig::make_thread_begin_step_runner;
  return p;
}

template <typename Model>
void step_bench(benchmark::State& state, const char* file, bool parallel) {
  Model m(load(file, parallel), 1e-3);
  Signals s = rig::test::cornering_inputs();
  m.set_forward_speed(15);
  for (int k = 0; k < 2000; ++k) (void)m.step(s);  // into a steady turn
  for (auto _ : state) {
    benchmark::DoNotOptimize(m.step(s));
  }
}

void BM_CarTrailerDae(benchmark::State& state) {
  step_bench<Combination>(state, kCarTrailer, false);
}
void BM_CarTrailerDaeParallel(benchmark::State& state) {
  step_bench<Combination>(state, kCarTrailer, true);
}
void BM_CarTrailerForceCoupled(benchmark::State& state) {
  step_bench<ForceCoupledCombination>(state, kCarTrailer, false);
}
void BM_TractorSemitrailerDae(benchmark::State& state) {
  step_bench<Combination>(state, kTractorSemi, false);
}
void BM_TractorSemitrailerDaeParallel(benchmark::State& state) {
  step_bench<Combination>(state, kTractorSemi, true);
}
void BM_TractorSemitrailerForceCoupled(benchmark::State& state) {
  step_bench<ForceCoupledCombination>(state, kTractorSemi, false);
}

// The 40 t tractor-semitrailer of issue 17 (tractor with cab, engine and seat; equalised tridem):
// at most 30 us per step on the 2-core CI machine.
void BM_TractorSemitrailer40tDae(benchmark::State& state) {
  step_bench<Combination>(state, kTractorSemi40t, false);
}

BENCHMARK(BM_CarTrailerDae);
BENCHMARK(BM_CarTrailerDaeParallel);
BENCHMARK(BM_CarTrailerForceCoupled);
BENCHMARK(BM_TractorSemitrailerDae);
BENCHMARK(BM_TractorSemitrailerDaeParallel);
BENCHMARK(BM_TractorSemitrailerForceCoupled);
BENCHMARK(BM_TractorSemitrailer40tDae);

}  // namespace

BENCHMARK_MAIN();
