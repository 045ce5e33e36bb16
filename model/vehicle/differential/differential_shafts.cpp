#include "model/vehicle/differential/differential_shafts.h"

#include <cmath>

#include <Eigen/Cholesky>

#include "model/solver/dry_friction.h"

namespace rig::model::vehicle::differential {

DifferentialShafts::DifferentialShafts(const VehicleParams& p, VehicleState& state,
                                       const VehicleWorkspace& work)
    : tree_(build_tree(p)),
      state_(state),
      work_(work),
      c_(p.drivetrain.half_shaft_stiffness_nmpr),
      d_(p.drivetrain.half_shaft_damping_nmspr) {}

void DifferentialShafts::begin_step(const VehicleInputs& inputs) noexcept {
  for (int j = 0; j < tree_.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const DifferentialParams& d = tree_.params[k];
    const bool lock_input = d.axle >= 0 ? inputs.lock_axle : inputs.lock_between;
    locked_[k] = d.kind == DifferentialKind::kLocked || (d.lockable && lock_input);
    capacity_nm_[k] = 0;
    if (d.kind != DifferentialKind::kLimitedSlip) continue;
    double input_nm = 0;  // the input torque of the step's start: its shafts' last torques
    for (int i = 0; i < tree_.leaf_count; ++i) {
      if (tree_.side(i, j) != 0)
        input_nm += state_.shaft_torque_nm[static_cast<std::size_t>(
            tree_.wheel[static_cast<std::size_t>(i)])];
    }
    const double sensing = (d.bias_ratio - 1.0) / (d.bias_ratio + 1.0);
    capacity_nm_[k] = 0.5 * (d.preload_nm + sensing * std::abs(input_nm));  // couple = T_L / 2
  }
}

void DifferentialShafts::reduce(const std::array<bool, kMaxDifferentials>& fixed, LeafMatrix& g,
                                DiffMatrix& k) const noexcept {
  g = tree_.g;
  for (int j = 0; j < tree_.count; ++j)
    if (fixed[static_cast<std::size_t>(j)]) g.col(j).setZero();
  k.resize(tree_.count, tree_.count);
  k.noalias() = d_ * g.transpose() * g;
  for (int j = 0; j < tree_.count; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    if (fixed[jj]) {  // delta_j = 0: a unit row and column
      k.row(j).setZero();
      k.col(j).setZero();
      k(j, j) = 1.0;
    } else if (tree_.params[jj].kind == DifferentialKind::kViscous) {
      k(j, j) += tree_.params[jj].viscous_nmspr;
    }
  }
}

void DifferentialShafts::clutches(const LeafVector& x, std::array<bool, kMaxDifferentials>& fixed,
                                  DiffVector& lambda) const noexcept {
  std::array<int, kMaxLimitedSlip> at{};
  int m = 0;
  for (int j = 0; j < tree_.count && m < kMaxLimitedSlip; ++j)
    if (!fixed[static_cast<std::size_t>(j)] && capacity_nm_[static_cast<std::size_t>(j)] > 0)
      at[static_cast<std::size_t>(m++)] = j;
  if (m == 0) return;
  LeafMatrix g;
  DiffMatrix k;
  reduce(fixed, g, k);
  const Eigen::LLT<DiffMatrix> llt(k);
  const DiffMatrix w = llt.solve(DiffMatrix::Identity(tree_.count, tree_.count));
  const DiffVector b = -llt.solve(g.transpose() * x);  // delta with the clutches open
  // delta = b + W lambda: each clutch sticks (delta_j = 0, |lambda_j| <= capacity) or slides
  solver::detail::Square4 ww{};
  solver::detail::Column4 bb{}, cc{};
  for (int p = 0; p < m; ++p) {
    const auto pp = static_cast<std::size_t>(p);
    bb[pp] = b(at[pp]);
    cc[pp] = capacity_nm_[static_cast<std::size_t>(at[pp])];
    for (int q = 0; q < m; ++q)
      ww[pp][static_cast<std::size_t>(q)] = w(at[pp], at[static_cast<std::size_t>(q)]);
  }
  const solver::FrictionSolution s = solver::solve_friction(ww, bb, cc, m, 1.0);
  for (int p = 0; p < m; ++p) {
    const auto pp = static_cast<std::size_t>(p);
    if (s.state[pp] == solver::FrictionState::kStick)
      fixed[static_cast<std::size_t>(at[pp])] = true;
    else
      lambda(at[pp]) = s.force[pp];
  }
}

void DifferentialShafts::solve(const Vector& s, double carrier_radps, ShaftSolution& out,
                               bool partials) const noexcept {
  LeafVector x(tree_.leaf_count);
  for (int i = 0; i < tree_.leaf_count; ++i) {
    const double spin =
        state_.spin_radps[static_cast<std::size_t>(tree_.wheel[static_cast<std::size_t>(i)])];
    x(i) = c_ * s(i) + d_ * (carrier_radps - spin);
  }
  out.fixed = locked_;
  DiffVector lambda = DiffVector::Zero(tree_.count);
  clutches(x, out.fixed, lambda);
  LeafMatrix g;
  DiffMatrix k;
  reduce(out.fixed, g, k);
  const Eigen::LLT<DiffMatrix> llt(k);
  out.delta_radps = llt.solve(lambda - g.transpose() * x);
  out.torque_nm = x + d_ * g * out.delta_radps;
  if (partials) out.s.noalias() = g * llt.solve(g.transpose());
}

void DifferentialShafts::rate(const Vector& s, Vector& f) const noexcept {
  ShaftSolution sol;
  solve(s, work_.carrier_speed_radps, sol);
  const LeafVector side = tree_.g * sol.delta_radps;
  for (int i = 0; i < tree_.leaf_count; ++i) {
    const double spin =
        state_.spin_radps[static_cast<std::size_t>(tree_.wheel[static_cast<std::size_t>(i)])];
    f(i) = work_.carrier_speed_radps + side(i) - spin;
  }
}

bool DifferentialShafts::rate_jacobian(const Vector& s, Matrix& df_ds) const noexcept {
  ShaftSolution sol;
  solve(s, work_.carrier_speed_radps, sol, true);
  df_ds = -c_ * sol.s;
  return true;
}

void DifferentialShafts::wheel_torques(
    double carrier_radps, double h, std::array<double, kMaxWheels>& torque_nm,
    std::array<double, kMaxWheels>& added_inertia_kgm2) const noexcept {
  ShaftSolution sol;
  solve(state_.shaft_twist_rad, carrier_radps, sol, true);
  for (int i = 0; i < tree_.leaf_count; ++i) {
    const auto k = static_cast<std::size_t>(tree_.wheel[static_cast<std::size_t>(i)]);
    torque_nm[k] = sol.torque_nm(i);
    added_inertia_kgm2[k] = h * (d_ - d_ * d_ * sol.s(i, i));
  }
}

double DifferentialShafts::carrier_torque_nm(double carrier_radps) const noexcept {
  ShaftSolution sol;
  solve(state_.shaft_twist_rad, carrier_radps, sol);
  return sol.torque_nm.sum();
}

void DifferentialShafts::speeds(
    double carrier_radps, std::array<DifferentialReport, kMaxDifferentials>& out) const noexcept {
  ShaftSolution sol;
  solve(state_.shaft_twist_rad, carrier_radps, sol);
  for (int j = 0; j < tree_.count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const double r = tree_.params[k].split;
    DifferentialReport& d = out[k];
    d.input_speed_radps = carrier_radps + tree_.input_row.row(j).dot(sol.delta_radps);
    d.output_a_speed_radps = d.input_speed_radps + (1.0 - r) * sol.delta_radps(j);
    d.output_b_speed_radps = d.input_speed_radps - r * sol.delta_radps(j);
    d.locked = sol.fixed[k] ? 1 : 0;
  }
}

}  // namespace rig::model::vehicle::differential
