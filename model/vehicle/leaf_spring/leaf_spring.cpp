#include "model/vehicle/leaf_spring/leaf_spring.h"

#include <cmath>

#include "model/vehicle/leaf_spring/small_solve.h"

namespace rig::model::vehicle::leaf_spring {

namespace {

using Kkt = Eigen::Matrix<double, 7, 7>;
using SeatCoupling = Eigen::Matrix<double, 7, 3>;

/// (x, z, pitch) <-> (x, z, theta): the leaf's angles turn from +x towards +z, pitch the other way.
const Eigen::Vector3d kIso(1.0, 1.0, -1.0);
constexpr double kMaxTurnRad = 0.2;

Coords compose(const Eigen::Vector3d& seat, const Internal& u) {
  Coords w;
  w << seat, u.head<kLinkCoords>();
  return w;
}

/// The bordered system of the internal equilibrium: residual r = (dL/dw_i, g), its Jacobian A
/// in the internal unknowns (link coordinates, lambda), and B = dr/d(seat).
struct Equilibrium {
  LeafTerms terms;
  Internal residual;
  Kkt a;
  SeatCoupling b;
};

void assemble(const LeafGeometry& g, const Eigen::Vector3d& seat, const Internal& u,
              Equilibrium& e) {
  leaf_terms(g, compose(seat, u), u.tail<2>(), e.terms);
  const LeafTerms& t = e.terms;
  e.residual << t.gradient.tail<kLinkCoords>(), t.closure_m;
  e.a.topLeftCorner<kLinkCoords, kLinkCoords>() =
      t.hessian.bottomRightCorner<kLinkCoords, kLinkCoords>();
  e.a.topRightCorner<kLinkCoords, 2>() = t.closure_jacobian.rightCols<kLinkCoords>().transpose();
  e.a.bottomLeftCorner<2, kLinkCoords>() = t.closure_jacobian.rightCols<kLinkCoords>();
  e.a.bottomRightCorner<2, 2>().setZero();
  e.b.topRows<kLinkCoords>() = t.hessian.bottomLeftCorner<kLinkCoords, kSeatCoords>();
  e.b.bottomRows<2>() = t.closure_jacobian.leftCols<kSeatCoords>();
}

bool within_tolerance(const LeafSpringParams& p, const Internal& r) {
  return r.head<kLinkCoords>().cwiseAbs().maxCoeff() <= p.tolerance_nm &&
         r.tail<2>().cwiseAbs().maxCoeff() <= p.closure_tolerance_m;
}

/// Forces and partials at the (converged) equilibrium `e`; updates the state's sensitivity.
void forces_at(const Equilibrium& e, const Eigen::Vector2d& bushing_npm, LeafState& state,
               LeafForces& out) {
  const LeafTerms& t = e.terms;
  Kkt a = e.a;
  SeatCoupling s = e.b;
  (void)solve_in_place(a, s);  // s = A^-1 B; d(internal)/d(seat) = -s
  state.d_internal_d_seat = -s;
  const Eigen::Matrix3d k_seat =
      t.hessian.topLeftCorner<kSeatCoords, kSeatCoords>() - e.b.transpose() * s;
  out.on_axle = -kIso.cwiseProduct(t.gradient.head<kSeatCoords>());
  out.d_on_axle_d_seat = -(kIso.asDiagonal() * k_seat * kIso.asDiagonal());
  const Eigen::Matrix<double, 2, 3> d_eye =
      t.eye_jacobian.leftCols<kSeatCoords>() -
      t.eye_jacobian.rightCols<kLinkCoords>() * s.topRows<kLinkCoords>();
  out.on_frame_at_eye_n = t.bushing_force_n;
  out.d_on_frame_at_eye_d_seat = bushing_npm.asDiagonal() * d_eye * kIso.asDiagonal();
  out.on_frame_at_pin_n = state.internal.tail<2>();
  out.d_on_frame_at_pin_d_seat = -s.bottomRows<2>() * kIso.asDiagonal();
  out.eye_m = t.eye_m;
  out.energy_j = t.energy_j;
}

}  // namespace

LeafSpring::LeafSpring(const LeafSpringParams& params)
    : params_(params), geometry_(make_leaf_geometry(params)) {}

LeafState LeafSpring::free_state() const noexcept {
  LeafState s;
  s.internal << free_coords(geometry_).tail<kLinkCoords>(), 0.0, 0.0;
  LeafState scratch = s;
  const LeafForces f = evaluate(SeatPose::Zero(), scratch);  // the sensitivity at rest
  s.d_internal_d_seat = scratch.d_internal_d_seat;
  (void)f;
  return s;
}

LeafForces LeafSpring::evaluate(const SeatPose& seat_pose, LeafState& state) const noexcept {
  const Eigen::Vector3d seat = kIso.cwiseProduct(seat_pose);
  // stage 1: predict from the last solution and its sensitivity (first order in the seat's move)
  Internal u = state.internal + state.d_internal_d_seat * (seat - state.seat);
  // stage 2: Newton on the bordered equilibrium
  Equilibrium e;
  LeafForces out;
  for (;;) {
    assemble(geometry_, seat, u, e);
    out.converged = within_tolerance(params_, e.residual);
    if (out.converged || out.iterations == params_.max_iterations || !e.residual.allFinite()) break;
    Kkt a = e.a;
    Internal step = e.residual;
    if (!solve_in_place(a, step)) break;
    // a jump of the seat (a reset without settle()) must not flip a link: at most kMaxTurnRad
    // per iteration; in a step of 1 ms the turns are below 1e-3 rad and this never acts
    const double turn = step.head<kLinkCoords>().cwiseAbs().maxCoeff();
    if (turn > kMaxTurnRad) step *= kMaxTurnRad / turn;
    u -= step;
    ++out.iterations;
  }
  // stage 3: forces and their partials (implicit function theorem); the new solution is kept
  // unless it is not finite (a NaN pose), so that the next sane pose starts from the last good one
  LeafState next = state;
  next.internal = u;
  next.seat = seat;
  forces_at(e, geometry_.bushing_npm, next, out);
  if (next.internal.allFinite() && next.d_internal_d_seat.allFinite()) state = next;
  return out;
}

bool LeafSpring::settle(const SeatPose& seat_pose, LeafState& state) const noexcept {
  state = free_state();
  constexpr int kSteps = 200;
  LeafForces f;
  for (int k = 1; k <= kSteps; ++k) {
    f = evaluate(seat_pose * (static_cast<double>(k) / kSteps), state);
  }
  for (int k = 0; k < 10 && !f.converged; ++k) f = evaluate(seat_pose, state);
  return f.converged;
}

}  // namespace rig::model::vehicle::leaf_spring
