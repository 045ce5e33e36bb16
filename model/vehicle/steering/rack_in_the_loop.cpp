#include "model/vehicle/steering/rack_in_the_loop.h"

#include <cmath>

namespace rig::model::vehicle {

RackInTheLoop::RackInTheLoop(const SteeringParams& p, VehicleState& state,
                             const VehicleInputs& inputs)
    : p_(p), state_(state), inputs_(inputs) {}

void RackInTheLoop::begin_step(double h) noexcept {
  (void)h;
  const double i = p_.rack_per_pinion_m_per_rad;
  const bool valid = inputs_.rack_measured_valid &&
                     std::isfinite(inputs_.rack_position_measured_m) &&
                     std::isfinite(inputs_.rack_speed_measured_mps);
  // invalid: hold the last position (the state's), at rest
  const double u = valid ? inputs_.rack_position_measured_m : state_.steering_y(1);
  const double v = valid ? inputs_.rack_speed_measured_mps : 0.0;
  state_.steering_y << u / i, u;
  state_.steering_z << v / i, v;
}

void RackInTheLoop::mass_matrix(const Vector& y, Matrix& m) const noexcept {
  (void)y;
  m << kPrescribedMassKg, 0, 0, kPrescribedMassKg;
}

void RackInTheLoop::applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept {
  (void)y;
  (void)z;
  q.setZero();
}

void RackInTheLoop::force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                                    Matrix& dq_dz) const noexcept {
  (void)y;
  (void)z;
  dq_dy.setZero();
  dq_dz.setZero();
}

double RackInTheLoop::torsion_bar_torque_nm(const Vector& y, const Vector& z) const noexcept {
  (void)y;
  (void)z;
  return 0.0;
}

double RackInTheLoop::assist_torque_nm(const Vector& y, const Vector& z) const noexcept {
  (void)y;
  (void)z;
  return 0.0;
}

}  // namespace rig::model::vehicle
