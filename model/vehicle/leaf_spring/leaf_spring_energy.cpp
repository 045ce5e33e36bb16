#include "model/vehicle/leaf_spring/leaf_spring_energy.h"

#include <cmath>

namespace rig::model::vehicle::leaf_spring {

namespace {

Eigen::Vector2d dir(double angle) { return {std::cos(angle), std::sin(angle)}; }
Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }  // d/dangle

/// A seat point (in the axle's frame) rotated by theta: its position, first and second
/// derivatives with respect to theta.
struct SeatPoint {
  Eigen::Vector2d r, dr, ddr;
};

/// cos and sin of the seat's rotation theta, taken once for both seat points.
struct SeatRotation {
  double c, s;
};

SeatPoint seat_point(const Eigen::Vector2d& local, const SeatRotation& rot) {
  const double c = rot.c;
  const double s = rot.s;
  const Eigen::Vector2d r(c * local.x() - s * local.y(), s * local.x() + c * local.y());
  return {r, perp(r), -r};
}

/// Four rotational springs, each 1/2 c d^2 with d linear in w (leaf_spring_params.h).
void add_springs(const LeafGeometry& g, const Coords& w, LeafTerms& out) {
  const double deflection[4] = {
      w(kFrontInner) - w(kTheta) - g.free_angle_rad(0),
      (w(kFrontOuter) - w(kFrontInner)) - (g.free_angle_rad(1) - g.free_angle_rad(0)),
      w(kRearInner) - w(kTheta) - g.free_angle_rad(2),
      (w(kRearOuter) - w(kRearInner)) - (g.free_angle_rad(3) - g.free_angle_rad(2))};
  const int plus[4] = {kFrontInner, kFrontOuter, kRearInner, kRearOuter};
  const int minus[4] = {kTheta, kFrontInner, kTheta, kRearInner};
  for (int k = 0; k < 4; ++k) {
    const double c = g.spring_nmprad(k);
    const double m = c * deflection[k];
    out.energy_j += 0.5 * m * deflection[k];
    out.gradient(plus[k]) += m;
    out.gradient(minus[k]) -= m;
    out.hessian(plus[k], plus[k]) += c;
    out.hessian(minus[k], minus[k]) += c;
    out.hessian(plus[k], minus[k]) -= c;
    out.hessian(minus[k], plus[k]) -= c;
  }
}

/// The front eye E = X + R(theta) S1 + l_SA e(a_S1A) + l_AE e(a_AE) on the bushing K_b.
void add_eye_bushing(const LeafGeometry& g, const Coords& w, const SeatRotation& rot,
                     LeafTerms& out) {
  const SeatPoint s1 = seat_point(g.seat_front_m, rot);
  const Eigen::Vector2d inner = g.front_inner_m * dir(w(kFrontInner));
  const Eigen::Vector2d outer = g.front_outer_m * dir(w(kFrontOuter));
  out.eye_m = Eigen::Vector2d(w(kX), w(kZ)) + s1.r + inner + outer;
  out.eye_jacobian.setZero();
  out.eye_jacobian(0, kX) = 1.0;
  out.eye_jacobian(1, kZ) = 1.0;
  out.eye_jacobian.col(kTheta) = s1.dr;
  out.eye_jacobian.col(kFrontInner) = perp(inner);
  out.eye_jacobian.col(kFrontOuter) = perp(outer);
  const Eigen::Vector2d stretch = out.eye_m - g.eye_frame_m;
  const Eigen::Vector2d f = g.bushing_npm.cwiseProduct(stretch);
  out.bushing_force_n = f;
  out.energy_j += 0.5 * stretch.dot(f);
  out.gradient.noalias() += out.eye_jacobian.transpose() * f;
  out.hessian.noalias() +=
      out.eye_jacobian.transpose() * g.bushing_npm.asDiagonal() * out.eye_jacobian;
  // f . d2E/dw2: only the angles have second derivatives (each of its own coordinate)
  out.hessian(kTheta, kTheta) += f.dot(s1.ddr);
  out.hessian(kFrontInner, kFrontInner) -= f.dot(inner);
  out.hessian(kFrontOuter, kFrontOuter) -= f.dot(outer);
}

/// g = S2 + rear links - shackle end; lambda . g into the Lagrangian.
void add_shackle_closure(const LeafGeometry& g, const Coords& w, const SeatRotation& rot,
                         const Eigen::Vector2d& lambda, LeafTerms& out) {
  const SeatPoint s2 = seat_point(g.seat_rear_m, rot);
  const Eigen::Vector2d inner = g.rear_inner_m * dir(w(kRearInner));
  const Eigen::Vector2d outer = g.rear_outer_m * dir(w(kRearOuter));
  const double psi = w(kShackle);
  const double sin_psi = std::sin(psi), cos_psi = std::cos(psi);
  const Eigen::Vector2d hang(sin_psi, cos_psi);  // pin minus shackle end, / l_sh
  const double l_sh = g.shackle_length_m;
  out.closure_m =
      Eigen::Vector2d(w(kX), w(kZ)) + s2.r + inner + outer - g.pin_frame_m + l_sh * hang;
  PointJacobian& G = out.closure_jacobian;
  G.setZero();
  G(0, kX) = 1.0;
  G(1, kZ) = 1.0;
  G.col(kTheta) = s2.dr;
  G.col(kRearInner) = perp(inner);
  G.col(kRearOuter) = perp(outer);
  G.col(kShackle) = l_sh * Eigen::Vector2d(cos_psi, -sin_psi);
  out.gradient.noalias() += G.transpose() * lambda;
  out.hessian(kTheta, kTheta) += lambda.dot(s2.ddr);
  out.hessian(kRearInner, kRearInner) -= lambda.dot(inner);
  out.hessian(kRearOuter, kRearOuter) -= lambda.dot(outer);
  out.hessian(kShackle, kShackle) -= l_sh * lambda.dot(hang);
}

}  // namespace

Coords free_coords(const LeafGeometry& g) noexcept {
  Coords w;
  w << 0.0, 0.0, 0.0, g.free_angle_rad(0), g.free_angle_rad(1), g.free_angle_rad(2),
      g.free_angle_rad(3), g.shackle_angle_free_rad;
  return w;
}

void leaf_terms(const LeafGeometry& g, const Coords& w, const Eigen::Vector2d& lambda,
                LeafTerms& out) noexcept {
  out.energy_j = 0.0;
  out.gradient.setZero();
  out.hessian.setZero();
  add_springs(g, w, out);
  const SeatRotation rot{std::cos(w(kTheta)), std::sin(w(kTheta))};
  add_eye_bushing(g, w, rot, out);
  add_shackle_closure(g, w, rot, lambda, out);
}

}  // namespace rig::model::vehicle::leaf_spring
