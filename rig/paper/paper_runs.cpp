#include "rig/paper/paper_runs.h"

#include <cmath>
#include <cstdio>

#include "model/paper/coupled_pendulums.h"
#include "model/paper/quarter_car.h"

namespace rig::paper {

using model::paper::CoupledPendulums;
using model::paper::QuarterCar;

namespace {
long step_count(double h, double t_end) { return std::lround(t_end / h); }
}  // namespace

std::vector<QuarterCarRow> run_quarter_car(double h, double t_end, int output_every) {
  QuarterCar car;
  std::vector<QuarterCarRow> rows;
  const long n = step_count(h, t_end);
  rows.reserve(static_cast<std::size_t>(n / output_every + 2));
  auto record = [&](double t, const model::paper::QuarterCarInputs& in) {
    rows.push_back({t, car.position_m(), car.speed_mps(), car.wheel_speed_radps(),
                    car.deflection_m(), car.tire_force_n(), in.drive_torque_nm,
                    car.brake_torque_nm()});
  };
  record(0.0, model::paper::paper_maneuver_inputs(0.0));
  for (long k = 0; k < n; ++k) {
    const auto in = model::paper::paper_maneuver_inputs(static_cast<double>(k) * h);
    car.step(h, in);
    if ((k + 1) % output_every == 0) record(static_cast<double>(k + 1) * h, in);
  }
  return rows;
}

std::vector<PendulumRow> run_pendulums_dae(double h, double t_end, int output_every,
                                           const model::solver::NewtonParams& newton) {
  CoupledPendulums p({}, newton);
  std::vector<PendulumRow> rows;
  const long n = step_count(h, t_end);
  rows.reserve(static_cast<std::size_t>(n / output_every + 2));
  rows.push_back({0.0, p.phi1_rad(), p.phi2_rad(), 0.0, p.constraint_violation_m(), 0});
  for (long k = 0; k < n; ++k) {
    const auto report = p.step(h);
    if ((k + 1) % output_every == 0) {
      rows.push_back({static_cast<double>(k + 1) * h, p.phi1_rad(), p.phi2_rad(), p.rod_force_n(),
                      p.constraint_violation_m(), report.iterations});
    }
  }
  return rows;
}

std::vector<PendulumRow> run_pendulums_spring(double h, double t_end, int output_every,
                                              const SpringReferenceParams& params) {
  SpringReference ref({}, params);
  std::vector<PendulumRow> rows;
  const long n = step_count(h, t_end);
  rows.reserve(static_cast<std::size_t>(n / output_every + 2));
  rows.push_back(
      {0.0, ref.phi1_rad(), ref.phi2_rad(), ref.rod_force_n(), ref.constraint_violation_m(), 0});
  for (long k = 0; k < n; ++k) {
    if ((k + 1) % output_every != 0) continue;
    const double t = static_cast<double>(k + 1) * h;
    ref.advance_to(t);
    rows.push_back(
        {t, ref.phi1_rad(), ref.phi2_rad(), ref.rod_force_n(), ref.constraint_violation_m(), 0});
  }
  return rows;
}

void write_csv(std::ostream& out, const std::vector<QuarterCarRow>& rows) {
  out << "t,x,v,omega,x_e,F_x,T_drive,T_brake\n";
  char line[320];
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", r.t, r.x, r.v,
                  r.omega, r.x_e, r.f_x, r.t_drive, r.t_brake);
    out << line;
  }
}

void write_csv(std::ostream& out, const std::vector<PendulumRow>& rows) {
  out << "t,phi1,phi2,lambda,g,newton_iterations\n";
  char line[256];
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%.6f,%.12g,%.12g,%.9g,%.6g,%d\n", r.t, r.phi1, r.phi2,
                  r.lambda, r.g, r.newton_iterations);
    out << line;
  }
}

}  // namespace rig::paper
