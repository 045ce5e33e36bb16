#include "model/vehicle/free_body/seat.h"

#include <cmath>

namespace rig::model::vehicle {

Seat::Seat(const FreeBodyParams& p, const road::Road& road, VehicleState& state,
           const VehicleWorkspace& work, int slot, const PredictedChassis& chassis)
    : MountedBody<1>(p, road, state, work, slot, chassis) {
  point_ = Vec3(p.position_m[0], p.position_m[1], p.position_m[2]);
  if (!p.mounts.empty()) {
    const MountParams& m = p.mounts.front();
    k_ = m.stiffness_npm[2];
    c_ = m.damping_nspm[2];
    clearance_ = m.stop_clearance_m[2];
    stop_k_ = m.stop_stiffness_npm[2];
  }
}

Seat::Vector& Seat::coordinates() noexcept { return state_.seat_y[slot()]; }
Seat::Vector& Seat::speeds() noexcept { return state_.seat_z[slot()]; }

void Seat::mass_matrix(const Vector& y, Matrix& m) const noexcept {
  (void)y;
  m(0, 0) = p_.mass_kg;
}

double Seat::suspension_force_n(double e, double e_rate) const noexcept {
  double f = -k_ * e - c_ * e_rate;
  const double beyond = std::abs(e) - clearance_;
  if (beyond > 0) f -= std::copysign(stop_k_ * beyond * (1 + beyond / p_.through_margin_m), e);
  return f;
}

Eigen::Vector2d Seat::point_height(const RigidPose& chassis) const noexcept {
  const Vec3 p = chassis.position_m + chassis.rot * point_;
  const Vec3 v = chassis.rot * (chassis.velocity_mps + chassis.rate_radps.cross(point_));
  return {p.z(), v.z()};
}

Eigen::Vector2d Seat::deflection(const RigidPose& chassis) const noexcept {
  const auto k = slot();
  return Eigen::Vector2d(state_.seat_y[k](0), state_.seat_z[k](0)) - point_height(chassis);
}

void Seat::applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept {
  const Eigen::Vector2d point = point_height(chassis_pose());
  q(0) =
      p_.mass_kg * road_.gravity_mps2().z() + suspension_force_n(y(0) - point(0), z(0) - point(1));
}

bool Seat::force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                           Matrix& dq_dz) const noexcept {
  (void)z;
  const Eigen::Vector2d point = point_height(chassis_pose());
  const double beyond = std::abs(y(0) - point(0)) - clearance_;
  double k = k_;
  if (beyond > 0) k += stop_k_ * (1 + 2 * beyond / p_.through_margin_m);
  dq_dy(0, 0) = -k;
  dq_dz(0, 0) = -c_;
  return true;
}

Vec6 Seat::chassis_load(const RigidPose& chassis) const noexcept {
  const Eigen::Vector2d e = deflection(chassis);
  const Vec3 f = chassis.rot.transpose() * Vec3(0, 0, -suspension_force_n(e(0), e(1)));
  Vec6 q;
  q << f, point_.cross(f);
  return q;
}

double Seat::beyond_stop_m(const RigidPose& chassis) const noexcept {
  return std::abs(deflection(chassis)(0)) - clearance_;
}

}  // namespace rig::model::vehicle
