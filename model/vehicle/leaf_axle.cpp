#include "model/vehicle/leaf_axle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "model/vehicle/leaf_balance.h"

namespace rig::model::vehicle {
namespace {

namespace ls = leaf_spring;

/// Balanced when the leaves take the housing's load to within these; what is left is taken out
/// to first order (the Newton step d = -K_ii^-1 r, q += K_ei d), whose error is second order:
/// at 2 N / 0.5 N m, d is ~1e-6 m / 6e-6 rad and the error in q below 1e-3 N (the leaves'
/// stiffness changes by ~10 % over 10 mm or 10 mrad).
constexpr double kForceTolerance = 2.0;   // N
constexpr double kMomentTolerance = 0.5;  // N m

/// The axle's dampers, stops and bar; the leaves are its springs (rate and preload 0 here).
AxleParams without_springs(const AxleParams& a) {
  AxleParams b = a;
  b.spring_stiffness_npm = 0;
  return b;
}

}  // namespace

LeafAxleSuspension::LeafAxleSuspension(int axle, const AxleParams& a, double preload_left_n,
                                       double preload_right_n, LeafAxleState& state)
    : leaf_(a.leaf_spring),
      others_(without_springs(a), 0.0, 0.0),
      half_track_m_(0.5 * a.rigid.spring_track_m),
      state_(&state) {
  rest_.axle = axle;
  settle_rest(preload_left_n, preload_right_n);
  *state_ = rest_;
}

LeafAxleSuspension::Both LeafAxleSuspension::evaluate(const Eigen::Vector2d& balance,
                                                      double heave_m, double roll_rad,
                                                      const Eigen::Vector2d& load,
                                                      LeafAxleState& s) const noexcept {
  Both b;
  b.generalized.setZero();
  b.stiffness.setZero();
  for (int side = 0; side < 2; ++side) {
    const auto k = static_cast<std::size_t>(side);
    const double lever = side == 0 ? half_track_m_ : -half_track_m_;
    const double z = rest_seat_z_m_[k] + heave_m + lever * roll_rad;
    b.leaf[k] = leaf_.evaluate(ls::SeatPose(balance(0), z, balance(1)), s.leaf[k]);
    // seat (x, z, pitch) = T (x, pitch, heave, roll)
    Eigen::Matrix<double, 3, 4> t;
    t << 1, 0, 0, 0, 0, 0, 1, lever, 0, 1, 0, 0;
    b.generalized.noalias() += t.transpose() * b.leaf[k].on_axle;
    b.stiffness.noalias() += t.transpose() * b.leaf[k].d_on_axle_d_seat * t;
  }
  b.residual = b.generalized.head<2>() + load;
  return b;
}

void LeafAxleSuspension::balance(double heave_m, double roll_rad, const Eigen::Vector2d& load,
                                 LeafAxleState& s) const noexcept {
  const Eigen::Vector2d y(heave_m, roll_rad);
  // warm start: the last balance moved on to first order with the load and the axle's travel
  Eigen::Vector2d b(s.x_m, s.pitch_rad);
  const Eigen::Vector2d predicted =
      b + s.d_balance_d_load * (load - s.load) + s.d_balance_d_y * (y - s.at);
  if (predicted.allFinite()) b = predicted;
  Both e;
  Eigen::Vector2d step;
  Eigen::Matrix2d kii_inv;
  s.iterations = {0, 0};
  s.balance_evaluations = 0;
  for (;;) {
    e = evaluate(b, heave_m, roll_rad, load, s);
    ++s.balance_evaluations;
    s.iterations[0] += e.leaf[0].iterations;
    s.iterations[1] += e.leaf[1].iterations;
    kii_inv = e.stiffness.topLeftCorner<2, 2>().inverse();
    step = -kii_inv * e.residual;  // Newton on (x, pitch): K_ii d = -residual
    const bool balanced =
        std::abs(e.residual(0)) <= kForceTolerance && std::abs(e.residual(1)) <= kMomentTolerance;
    if (balanced || s.balance_evaluations >= kMaxBalanceEvaluations || !step.allFinite()) break;
    b += step;
  }
  const Eigen::Matrix2d k_ie = e.stiffness.topRightCorner<2, 2>();
  const Eigen::Matrix2d k_ei = e.stiffness.bottomLeftCorner<2, 2>();
  s.d_balance_d_load = -kii_inv;
  s.d_balance_d_y = -kii_inv * k_ie;
  // what is left of the imbalance taken out to first order; the Schur complement
  s.q = e.generalized.tail<2>() + k_ei * step;
  s.dq_dy = e.stiffness.bottomRightCorner<2, 2>() + k_ei * s.d_balance_d_y;
  s.x_m = b(0) + step(0);
  s.pitch_rad = b(1) + step(1);
  s.at = y;
  s.load = load;
  for (std::size_t k = 0; k < 2; ++k) s.spring_n[k] = -e.leaf[k].on_axle(1);
}

void LeafAxleSuspension::forces_under_load(double heave_m, double roll_rad, double heave_rate_mps,
                                           double roll_rate_radps, const AxleHousingLoad& load,
                                           AxleSuspensionForces& out) const noexcept {
  if (group_ != nullptr) {  // balanced with its tandem partner in prepare(): at `at` exactly
    forces(heave_m, roll_rad, heave_rate_mps, roll_rate_radps, out);
    return;
  }
  others_.forces(heave_m, roll_rad, heave_rate_mps, roll_rate_radps, out);
  LeafAxleState& s = *state_;
  balance(heave_m, roll_rad, Eigen::Vector2d(load.force_x_n, load.moment_y_nm), s);
  out.q += s.q;
  out.dq_dy += s.dq_dy;
  out.spring_n[0] += s.spring_n[0];
  out.spring_n[1] += s.spring_n[1];
}

void LeafAxleSuspension::prepare(double heave_m, double roll_rad,
                                 const AxleHousingLoad& load) const noexcept {
  if (group_ != nullptr) group_->take(role_, heave_m, roll_rad, load);
}

void LeafAxleSuspension::forces(double heave_m, double roll_rad, double heave_rate_mps,
                                double roll_rate_radps, AxleSuspensionForces& out) const noexcept {
  // the last balance's first-order model (the Jacobians; the wheels' reported spring force)
  others_.forces(heave_m, roll_rad, heave_rate_mps, roll_rate_radps, out);
  const LeafAxleState& s = *state_;
  out.q += s.q + s.dq_dy * (Eigen::Vector2d(heave_m, roll_rad) - s.at);
  out.dq_dy += s.dq_dy;
  out.spring_n[0] += s.spring_n[0];
  out.spring_n[1] += s.spring_n[1];
}

void LeafAxleSuspension::settle_rest(double preload_left_n, double preload_right_n) {
  // unknowns u = (x, pitch, z_left, z_right): no fore-aft force, no moment, each leaf carrying
  // its static load (on_axle F_z = -preload: the leaf pushes the axle down)
  const std::array<double, 2> preload{preload_left_n, preload_right_n};
  // first guess: a van leaf's rate, but short of the free camber - a truck's heavier preload
  // over that rate would start the leaf beyond flat, where Newton finds it turned inside out
  const double rate_guess_npm = 1e5, most_m = 0.9 * leaf_.params().free_camber_m;
  Eigen::Vector4d u(0, 0, std::min(preload[0] / rate_guess_npm, most_m),
                    std::min(preload[1] / rate_guess_npm, most_m));
  for (std::size_t k = 0; k < 2; ++k) {
    rest_.leaf[k] = leaf_.free_state();
    leaf_.settle(ls::SeatPose(u(0), u(2 + k), u(1)), rest_.leaf[k]);
  }
  for (int n = 0; n < 200; ++n) {
    Eigen::Vector4d r;
    Eigen::Matrix4d j = Eigen::Matrix4d::Zero();
    bool converged = true;
    r.head<2>().setZero();
    for (std::size_t k = 0; k < 2; ++k) {
      const ls::LeafForces f = leaf_.evaluate(ls::SeatPose(u(0), u(2 + k), u(1)), rest_.leaf[k]);
      converged = converged && f.converged;
      r(0) += f.on_axle(0);
      r(1) += f.on_axle(2);
      r(2 + k) = f.on_axle(1) + preload[k];
      // columns x, pitch, z_k of the seat pose's (x, z, pitch)
      const Eigen::Matrix3d& d = f.d_on_axle_d_seat;
      j.block<1, 2>(0, 0) += Eigen::RowVector2d(d(0, 0), d(0, 2));
      j.block<1, 2>(1, 0) += Eigen::RowVector2d(d(2, 0), d(2, 2));
      j(0, 2 + k) = d(0, 1);
      j(1, 2 + k) = d(2, 1);
      j.block<1, 2>(2 + k, 0) = Eigen::RowVector2d(d(1, 0), d(1, 2));
      j(2 + k, 2 + k) = d(1, 1);
    }
    const double scale = 1e-9 * (1.0 + std::abs(preload[0]) + std::abs(preload[1]));
    if (converged && r.cwiseAbs().maxCoeff() < scale) {
      rest_seat_z_m_ = {u(2), u(3)};
      rest_.x_m = rest_.rest_x_m = u(0);
      rest_.pitch_rad = rest_.rest_pitch_rad = u(1);
      balance(0.0, 0.0, Eigen::Vector2d::Zero(), rest_);
      return;
    }
    Eigen::Vector4d du = -j.fullPivLu().solve(r);
    // a leaf may only move a few centimetres per step (its own Newton follows)
    const double largest = du.cwiseAbs().maxCoeff();
    if (largest > 0.02) du *= 0.02 / largest;
    if (!du.allFinite()) break;
    u += du;
  }
  throw std::invalid_argument("axle " + std::to_string(rest_.axle + 1) +
                              ": the leaf springs find no rest under the static loads " +
                              std::to_string(preload[0]) + " / " + std::to_string(preload[1]) +
                              " N");
}

}  // namespace rig::model::vehicle
