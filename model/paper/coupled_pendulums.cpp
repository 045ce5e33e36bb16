#include "model/paper/coupled_pendulums.h"

#include <cmath>

namespace rig::model::paper {

RodGeometry rod_geometry(const CoupledPendulumsParams& p, double phi1_rad,
                         double phi2_rad) noexcept {
  const double a1 = p.length1_m;
  const double a2 = p.length2_m;
  const double s1 = std::sin(phi1_rad), c1 = std::cos(phi1_rad);
  const double s2 = std::sin(phi2_rad), c2 = std::cos(phi2_rad);
  RodGeometry r;
  r.x_m = p.pivot_distance_m + a2 * s2 - a1 * s1;
  r.z_m = a2 * c2 - a1 * c1;
  r.length_m = std::hypot(r.x_m, r.z_m);
  r.dl_dphi1_m = (r.x_m * (-a1 * c1) + r.z_m * (a1 * s1)) / r.length_m;
  r.dl_dphi2_m = (r.x_m * (a2 * c2) + r.z_m * (-a2 * s2)) / r.length_m;  // not -a1 (typo)
  return r;
}

double rod_length_m(const CoupledPendulumsParams& p) noexcept {
  return rod_geometry(p, p.phi1_0_rad, p.phi2_0_rad).length_m;
}

Pendulum::Pendulum(double mass_kg, double length_m, double gravity_mps2, double phi0_rad)
    : mass_kg_(mass_kg), length_m_(length_m), gravity_mps2_(gravity_mps2) {
  y_(0) = phi0_rad;
  z_(0) = 0.0;
}

void Pendulum::kinematics_inverse(const Vector&, Matrix& k_inv) const noexcept {
  k_inv(0, 0) = 1.0 / length_m_;  // a phi' = v
}

void Pendulum::mass_matrix(const Vector&, Matrix& m) const noexcept { m(0, 0) = mass_kg_; }

void Pendulum::applied_forces(const Vector& y, const Vector&, Vector& q) const noexcept {
  q(0) = -mass_kg_ * gravity_mps2_ * std::sin(y(0));
}

bool Pendulum::force_jacobians(const Vector& y, const Vector&, Matrix& dq_dy,
                               Matrix& dq_dz) const noexcept {
  dq_dy(0, 0) = -mass_kg_ * gravity_mps2_ * std::cos(y(0));
  dq_dz(0, 0) = 0.0;
  return true;
}

void RodConstraint::evaluate(const Eigen::Ref<const Eigen::VectorXd>& y,
                             Eigen::Ref<Eigen::VectorXd> g,
                             Eigen::Ref<Eigen::MatrixXd> dg_dy) const noexcept {
  const RodGeometry r = rod_geometry(params_, y(0), y(1));
  g(0) = r.length_m - rod_length_m_;
  dg_dy(0, 0) = r.dl_dphi1_m;
  dg_dy(0, 1) = r.dl_dphi2_m;
}

solver::NewtonParams default_pendulum_newton_params() noexcept {
  solver::NewtonParams p;
  p.criterion = solver::NewtonCriterion::kPositionAndMultiplier;
  p.position_tolerance = 1e-7;
  p.multiplier_rel_tolerance = 1e-4;
  p.multiplier_abs_tolerance = 1e-3;
  p.max_iterations = 20;
  return p;
}

namespace {
solver::JacobianMode jacobian_mode(PendulumScheme scheme) {
  return scheme == PendulumScheme::kPaperListing
             ? solver::JacobianMode::kNone
             : solver::JacobianMode::kAnalyticOrFiniteDifference;
}
solver::ForceEvaluation force_evaluation(PendulumScheme scheme) {
  return scheme == PendulumScheme::kPaperListing ? solver::ForceEvaluation::kCurrentCoordinates
                                                 : solver::ForceEvaluation::kPredictedCoordinates;
}
}  // namespace

CoupledPendulums::CoupledPendulums(const CoupledPendulumsParams& params,
                                   const solver::NewtonParams& newton, PendulumScheme scheme)
    : params_(params),
      rod_length_m_(paper::rod_length_m(params)),
      pendulum1_(params.mass1_kg, params.length1_m, params.gravity_mps2, params.phi1_0_rad),
      pendulum2_(params.mass2_kg, params.length2_m, params.gravity_mps2, params.phi2_0_rad),
      stepper1_(pendulum1_, jacobian_mode(scheme), force_evaluation(scheme)),
      stepper2_(pendulum2_, jacobian_mode(scheme), force_evaluation(scheme)),
      rod_(params, rod_length_m_),
      coupled_({&stepper1_, &stepper2_}, rod_, newton) {}

solver::NewtonReport CoupledPendulums::step(double h) noexcept {
  const solver::NewtonReport report = coupled_.step(h);
  time_s_ += h;
  return report;
}

double CoupledPendulums::mechanical_energy_j() const noexcept {
  const CoupledPendulumsParams& p = params_;
  const double v1 = speed1_mps(), v2 = speed2_mps();
  return 0.5 * p.mass1_kg * v1 * v1 + 0.5 * p.mass2_kg * v2 * v2 -
         p.mass1_kg * p.gravity_mps2 * p.length1_m * std::cos(phi1_rad()) -
         p.mass2_kg * p.gravity_mps2 * p.length2_m * std::cos(phi2_rad());
}

double CoupledPendulums::constraint_violation_m() const noexcept {
  return rod_geometry(params_, phi1_rad(), phi2_rad()).length_m - rod_length_m_;
}

}  // namespace rig::model::paper
