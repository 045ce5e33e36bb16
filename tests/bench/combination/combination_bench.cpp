// One coupled step of the car + trailer and the tractor + semitrailer (issue 7): the DAE
// coupling (Newton on lambda, eqs. 45-50) serial and with the parallel begin_step, against the
// force-coupled big implicit matrix (eqs. 32-38); in a steady turn while driving, so that every
// force law and all joint rows are active.
#include <cmath>

#include <benchmark/benchmark.h>

#include "io/config/combination_file.h"
#include "io/config/strict_table.h"
#include "io/config/vehicle_file.h"
#include "model/combination/combination.h"
#include "model/combination/force_coupled.h"
#include "rig/thread_begin_step_runner.h"

namespace {

using rig::model::Signal;
using rig::model::Signals;
using rig::model::combination::Combination;
using rig::model::combination::CombinationParams;
using rig::model::combination::ForceCoupledCombination;

constexpr const char* kCarTrailer = RIG_SOURCE_DIR "/config/combinations/car-trailer.toml";
constexpr const char* kTractorSemi = RIG_SOURCE_DIR "/config/combinations/tractor-semitrailer.toml";

CombinationParams load(const char* file, bool parallel) {
  const toml::table doc = rig::io::config::load_toml_file(file);
  rig::io::config::StrictTable top(doc, file, "top level");
  rig::io::config::StrictTable m = top.table("model");
  (void)m.string("kind");
  const auto s = rig::io::config::read_combination_model(m);
  CombinationParams p;
  p.units = s.units;
  p.joints = s.joints;
  p.parallel = parallel;
  p.begin_step_runner = rig::make_thread_begin_step_runner;
  p.newton = rig::model::combination::default_combination_newton_params();
  return p;
}

Signals inputs() {
  Signals s;
  for (std::size_t i = 0; i < rig::model::index(rig::model::kFirstOutput); ++i) s.valid[i] = true;
  s[Signal::kGearRequest] = 99;
  s[Signal::kThrottlePedal] = 0.3;
  s[Signal::kSteeringWheelAngleCmd] = 0.5;
  return s;
}

template <typename Model>
void step_bench(benchmark::State& state, const char* file, bool parallel) {
  Model m(load(file, parallel), 1e-3);
  Signals s = inputs();
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

BENCHMARK(BM_CarTrailerDae);
BENCHMARK(BM_CarTrailerDaeParallel);
BENCHMARK(BM_CarTrailerForceCoupled);
BENCHMARK(BM_TractorSemitrailerDae);
BENCHMARK(BM_TractorSemitrailerDaeParallel);
BENCHMARK(BM_TractorSemitrailerForceCoupled);

}  // namespace

BENCHMARK_MAIN();
