#pragma once
/// @file
/// The paper's two validation runs as tables, shared by the rig-paper tool, the tests and the
/// benchmarks. CSV columns (exactly, in this order):
///   quarter car: t, x, v, omega, x_e, F_x, T_drive, T_brake
///     (s, m, m/s, rad/s, m, N, N m, N m; T_brake > 0 opposes forward wheel spin)
///   pendulums:   t, phi1, phi2, lambda, g, newton_iterations
///     (s, rad, rad, N, m, -; lambda = rod force, tension positive; the spring reference writes
///      its spring force c (l - s) + d l' there and 0 iterations)

#include <ostream>
#include <vector>

#include "model/paper/coupled_pendulums.h"
#include "model/solver/constraint_coupling.h"
#include "rig/paper/spring_reference.h"

namespace rig::paper {

struct QuarterCarRow {
  double t, x, v, omega, x_e, f_x, t_drive, t_brake;
};

struct PendulumRow {
  double t, phi1, phi2, lambda, g;
  int newton_iterations;
};

/// The quarter car on the paper's maneuver with step h up to t_end; a row at t = 0 and then
/// every output_every-th step.
std::vector<QuarterCarRow> run_quarter_car(double h, double t_end, int output_every = 1);

/// The pendulums as the index-3 DAE (modified implicit Euler + Newton on lambda); a row at t = 0
/// (lambda unknown there: 0) and after every output_every-th step.
std::vector<PendulumRow> run_pendulums_dae(
    double h, double t_end, int output_every = 1,
    const model::solver::NewtonParams& newton = model::paper::default_pendulum_newton_params());

/// The CVODE spring-damper reference sampled at multiples of h (rows as for the DAE).
std::vector<PendulumRow> run_pendulums_spring(double h, double t_end, int output_every = 1,
                                              const SpringReferenceParams& params = {});

void write_csv(std::ostream& out, const std::vector<QuarterCarRow>& rows);
void write_csv(std::ostream& out, const std::vector<PendulumRow>& rows);

}  // namespace rig::paper
