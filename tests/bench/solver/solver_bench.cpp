// Benchmarks of the model core: a quarter-car step, a pendulum DAE step, and the CPU time per
// simulated second of the pendulum DAE at h = 1 ms against the CVODE spring-damper reference.
#include <ctime>
#include <memory>

#include <benchmark/benchmark.h>

#include "model/paper/coupled_pendulums.h"
#include "model/paper/quarter_car.h"
#include "model/solver/arrowhead_factorization.h"
#include "model/solver/dense_factorization.h"
#include "rig/paper/spring_reference.h"

namespace {

using rig::model::paper::CoupledPendulums;
using rig::model::paper::paper_maneuver_inputs;
using rig::model::paper::QuarterCar;

double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

void BM_QuarterCarStep(benchmark::State& state) {
  constexpr double h = 1e-3;
  auto car = std::make_unique<QuarterCar>();
  long k = 0;
  for (auto _ : state) {
    car->step(h, paper_maneuver_inputs(static_cast<double>(k) * h));
    benchmark::DoNotOptimize(car->speed_mps());
    if (++k == 20000) {  // the whole maneuver, then again
      state.PauseTiming();
      car = std::make_unique<QuarterCar>();
      k = 0;
      state.ResumeTiming();
    }
  }
}
BENCHMARK(BM_QuarterCarStep);

void BM_PendulumDaeStep(benchmark::State& state) {
  constexpr double h = 1e-3;
  auto p = std::make_unique<CoupledPendulums>();
  long k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(p->step(h));
    if (++k == 5000) {
      state.PauseTiming();
      p = std::make_unique<CoupledPendulums>();
      k = 0;
      state.ResumeTiming();
    }
  }
}
BENCHMARK(BM_PendulumDaeStep);

// CPU seconds per simulated second over the paper's 5 s run: the DAE at h = 1 ms vs CVODE
// (BDF, rtol 1e-10, atol 1e-12) on the spring-damper rod, CVODE choosing its own steps and
// asked for output once per millisecond (what a 1 ms real-time loop needs), or only at the end.
void BM_PendulumCpuPerSimulatedSecond(benchmark::State& state) {
  double dae_s = 0, cvode_ms_s = 0, cvode_free_s = 0;
  long runs = 0;
  for (auto _ : state) {
    double t0 = thread_cpu_s();
    CoupledPendulums p;
    for (int i = 0; i < 5000; ++i) benchmark::DoNotOptimize(p.step(1e-3));
    double t1 = thread_cpu_s();
    dae_s += t1 - t0;
    rig::paper::SpringReference per_ms;
    for (int i = 1; i <= 5000; ++i) per_ms.advance_to(i * 1e-3);
    double t2 = thread_cpu_s();
    cvode_ms_s += t2 - t1;
    rig::paper::SpringReference free_run;
    free_run.advance_to(5.0);
    benchmark::DoNotOptimize(free_run.phi1_rad());
    cvode_free_s += thread_cpu_s() - t2;
    ++runs;
  }
  const double sim_s = 5.0 * static_cast<double>(runs);
  state.counters["dae_cpu_ms_per_sim_s"] = 1e3 * dae_s / sim_s;
  state.counters["cvode_1ms_out_cpu_ms_per_sim_s"] = 1e3 * cvode_ms_s / sim_s;
  state.counters["cvode_free_cpu_ms_per_sim_s"] = 1e3 * cvode_free_s / sim_s;
  state.counters["ratio_cvode_1ms_out_over_dae"] = cvode_ms_s / dae_s;
  state.counters["ratio_cvode_free_over_dae"] = cvode_free_s / dae_s;
}
BENCHMARK(BM_PendulumCpuPerSimulatedSecond)->Unit(benchmark::kMillisecond);

// Factorization + one solve of a vehicle-sized M_VI (eqs. 30-31): body 6 DOF, two axles of
// 10 DOF each (hub travels, spins, compliant axle states), dense LU vs the arrowhead form.
Eigen::MatrixXd vehicle_like_matrix(const rig::model::solver::ArrowheadPartition& p) {
  const Eigen::Index n = p.total_size();
  Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n);
  a.diagonal().array() += static_cast<double>(n);
  Eigen::Index o1 = p.body_size;
  for (std::size_t i = 0; i < p.leaf_sizes.size(); ++i) {
    Eigen::Index o2 = p.body_size;
    for (std::size_t j = 0; j < p.leaf_sizes.size(); ++j) {
      if (i != j) a.block(o1, o2, p.leaf_sizes[i], p.leaf_sizes[j]).setZero();
      o2 += p.leaf_sizes[j];
    }
    o1 += p.leaf_sizes[i];
  }
  return a;
}

void BM_MviDense26(benchmark::State& state) {
  const rig::model::solver::ArrowheadPartition p{6, {10, 10}};
  const Eigen::MatrixXd a = vehicle_like_matrix(p);
  rig::model::solver::DenseFactorization<Eigen::Dynamic> f(p.total_size());
  const Eigen::VectorXd b = Eigen::VectorXd::Random(p.total_size());
  Eigen::VectorXd x(p.total_size());
  for (auto _ : state) {
    f.compute(a);
    f.solve(b, x);
    benchmark::DoNotOptimize(x.data());
  }
}
BENCHMARK(BM_MviDense26);

void BM_MviArrowhead26(benchmark::State& state) {
  const rig::model::solver::ArrowheadPartition p{6, {10, 10}};
  const Eigen::MatrixXd a = vehicle_like_matrix(p);
  rig::model::solver::ArrowheadFactorization f(p);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(p.total_size());
  Eigen::VectorXd x(p.total_size());
  for (auto _ : state) {
    f.compute(a);
    f.solve(b, x);
    benchmark::DoNotOptimize(x.data());
  }
}
BENCHMARK(BM_MviArrowhead26);

}  // namespace

BENCHMARK_MAIN();
