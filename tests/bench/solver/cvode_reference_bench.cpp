// CPU time per simulated second of the pendulum DAE at h = 1 ms against the SUNDIALS CVODE
// spring-damper reference (rig/paper; part of solver_bench where SUNDIALS is found).
#include <ctime>

#include <benchmark/benchmark.h>

#include "model/paper/coupled_pendulums.h"
#include "rig/paper/spring_reference.h"

namespace {

using rig::model::paper::CoupledPendulums;

double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

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

}  // namespace
