#include "model/vehicle/steering/enhanced_steering.h"

#include "model/vehicle/wheel_spin.h"

namespace rig::model::vehicle {

EnhancedSteering::EnhancedSteering(const VehicleParams& p, SteeringSystem& system,
                                   VehicleState& state, VehicleWorkspace& work)
    : p_(p), system_(system), state_(state), work_(work) {
  for (int i = 0; i < 2 * static_cast<int>(p.axles.size()) && i < kMaxWheels; ++i) {
    if (p.axles[static_cast<std::size_t>(i / 2)].steered)
      wheel_[static_cast<std::size_t>(knuckles_++)] = i;
  }
  y_ = Vector::Zero(2 + knuckles_);
  z_ = Vector::Zero(2 + knuckles_);
}

void EnhancedSteering::gather() noexcept {
  y_.head<2>() = state_.steering_y;
  z_.head<2>() = state_.steering_z;
  for (int j = 0; j < knuckles_; ++j) {
    const auto k = static_cast<std::size_t>(wheel_[static_cast<std::size_t>(j)]);
    y_(2 + j) = state_.rack_at_wheel_m[k];
    z_(2 + j) = state_.knuckle_rate_mps[k];
    // the tire's loads at the step's start, explicit over the step (sec. 2.2: the wheel side)
    axis_moment_nm_[static_cast<std::size_t>(j)] =
        wheel_steering_axis_moment_nm(p_, state_, work_.wheels[k], static_cast<int>(k));
  }
}

void EnhancedSteering::scatter() noexcept {
  state_.steering_y = y_.head<2>();
  state_.steering_z = z_.head<2>();
  for (int j = 0; j < knuckles_; ++j) {
    const auto k = static_cast<std::size_t>(wheel_[static_cast<std::size_t>(j)]);
    state_.rack_at_wheel_m[k] = y_(2 + j);
    state_.knuckle_rate_mps[k] = z_(2 + j);
    work_.wheels[k].tie_rod_force_n = tie_rod_force_n(y_, z_, j);
  }
}

double EnhancedSteering::tie_rod_force_n(const Vector& y, const Vector& z, int j) const noexcept {
  const SteeringParams& s = p_.steering;
  return s.tie_rod_stiffness_npm * (y(1) - y(2 + j)) + s.tie_rod_damping_nspm * (z(1) - z(2 + j));
}

void EnhancedSteering::mass_matrix(const Vector& y, Matrix& m) const noexcept {
  SteeringSystem::Matrix m2;
  system_.mass_matrix(y.head<2>(), m2);
  m.setZero();
  m.topLeftCorner<2, 2>() = m2;
  for (int j = 0; j < knuckles_; ++j) {
    // Theta gamma'^2 / 2 = Theta (dgamma/du)^2 u_k'^2 / 2, dgamma/du frozen at the step's pose
    const double g =
        work_.wheels[static_cast<std::size_t>(wheel_[static_cast<std::size_t>(j)])].steer_d_du;
    m(2 + j, 2 + j) = p_.steering.knuckle_inertia_kgm2 * g * g;
  }
}

void EnhancedSteering::applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept {
  SteeringSystem::Vector q2;
  system_.applied_forces(y.head<2>(), z.head<2>(), q2);
  q(0) = q2(0);
  q(1) = q2(1);
  for (int j = 0; j < knuckles_; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    const double g = work_.wheels[static_cast<std::size_t>(wheel_[jj])].steer_d_du;
    const double f = tie_rod_force_n(y, z, j);
    q(1) -= f;
    q(2 + j) = axis_moment_nm_[jj] * g + f;  // virtual work: delta gamma = dgamma/du delta u_k
  }
}

void EnhancedSteering::dry_friction(const Vector& y, const Vector& z,
                                    solver::FrictionSet<Eigen::Dynamic>& contacts) const noexcept {
  const SteeringFriction f = system_.dry_friction(y.head<2>(), z.head<2>());
  contacts.clear();
  contacts.add_on_coordinate(0, f.column_nm);
  contacts.add_on_coordinate(1, f.rack_n);
}

bool EnhancedSteering::force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                                       Matrix& dq_dz) const noexcept {
  SteeringSystem::Matrix sy, sz;
  system_.force_jacobians(y.head<2>(), z.head<2>(), sy, sz);
  dq_dy.setZero();
  dq_dz.setZero();
  dq_dy.topLeftCorner<2, 2>() = sy;
  dq_dz.topLeftCorner<2, 2>() = sz;
  const double c = p_.steering.tie_rod_stiffness_npm, d = p_.steering.tie_rod_damping_nspm;
  for (int j = 0; j < knuckles_; ++j) {
    // the tie rod's spring-damper between rack (1) and knuckle (2 + j): the stiff part
    dq_dy(1, 1) -= c;
    dq_dy(1, 2 + j) = c;
    dq_dy(2 + j, 1) = c;
    dq_dy(2 + j, 2 + j) = -c;
    dq_dz(1, 1) -= d;
    dq_dz(1, 2 + j) = d;
    dq_dz(2 + j, 1) = d;
    dq_dz(2 + j, 2 + j) = -d;
  }
  return true;
}

}  // namespace rig::model::vehicle
