#include "model/vehicle/wheel_spin.h"

#include <cmath>

#include "model/vehicle/tire_deflection.h"

namespace rig::model::vehicle {

WheelSpinStage::WheelSpinStage(VehicleBus& bus, const VehicleParams& p,
                               const std::array<int, kMaxWheels>& axle_of_wheel,
                               const HalfShafts* shafts, Steering& steering,
                               const Drivetrain& drivetrain)
    : bus_(bus),
      p_(p),
      axle_of_wheel_(axle_of_wheel),
      shafts_(shafts),
      steering_(steering),
      drivetrain_(drivetrain) {
  if (shafts_ != nullptr) {
    for (int i = 0; i < shafts_->count(); ++i)
      driven_[static_cast<std::size_t>(shafts_->wheel(i))] = true;
  }
}

void WheelSpinStage::advance(double h) noexcept {
  // Tie-rod linkage (quasi-static compliance) from the new rack travel; the wheel's steer is
  // gamma(z, u) of the kinematic tables (SuspensionKinematics, eq. 29).
  const double rack = steering_.coordinates()(1);
  const SteeringParams& sp = p_.steering;
  double rack_force = 0;
  for (int i = 0; i < bus_.wheel_count; ++i) {
    WheelBus& w = bus_.wheels[static_cast<std::size_t>(i)];
    if (!p_.axles[static_cast<std::size_t>(axle_of_wheel_[static_cast<std::size_t>(i)])].steered)
      continue;
    // the aligning torque F_y n loads the rack by virtual work: F_rack = M dgamma/du
    w.tie_rod_force_n = w.force_y_n * sp.trail_m * w.steer_d_du;
    w.rack_at_wheel_m = rack - w.tie_rod_force_n / sp.tie_rod_stiffness_npm;
    // gamma of eq. (29) at the new rack travel, linear in u about the step's pose
    set_wheel_orientation(
        w, w.steer_kinematic_rad + w.steer_d_du * (w.rack_at_wheel_m - w.steer_at_rack_m),
        w.camber_rad);
    rack_force += w.tie_rod_force_n;
  }
  bus_.rack_force_n = rack_force;

  bus_.carrier_speed_radps = drivetrain_.carrier_speed_radps();  // newest (eq. 8 order)
  double shaft_torque = 0;
  if (shafts_ != nullptr)
    shaft_torque = shafts_->shaft_torque_nm(shafts_->state_const(), bus_.carrier_speed_radps);
  for (int i = 0; i < bus_.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    WheelBus& w = bus_.wheels[k];
    const TireParams& tire = p_.axles[static_cast<std::size_t>(axle_of_wheel_[k])].tire;
    const double r = w.radius_dynamic_m;
    const double xe = bus_.deflection_m[2 * k];
    const double f_per_slip = w.f_per_slip;  // eq. (16) at the start of the step
    const double rolling = r * std::abs(w.spin_radps);
    const double rate =
        deflection_rate(xe, w.vx_mps - r * w.spin_radps, rolling, w.curves.normalize_x, f_per_slip,
                        tire.longitudinal_stiffness_npm, tire.longitudinal_damping_nspm);
    const double fx = tire.longitudinal_stiffness_npm * xe + tire.longitudinal_damping_nspm * rate;
    // d F_x / d w through the damping path (eq. 24, at fixed f)
    const double denom =
        tire.longitudinal_damping_nspm * rolling * w.curves.normalize_x + f_per_slip + 1e-9;
    const double dfx_dw = tire.longitudinal_damping_nspm * f_per_slip * r / denom;
    double inertia = tire.spin_inertia_kgm2 + h * r * dfx_dw;
    const double ts = driven_[k] ? shaft_torque : 0.0;
    if (driven_[k])
      inertia += h * shafts_->d_torque_d_carrier() / static_cast<double>(shafts_->count());
    w.shaft_torque_nm = ts;
    const double other = ts - r * fx;
    // Stick prediction: the friction torque that makes w(k+1) = 0.
    const double stick = other + inertia * w.spin_radps / h;
    const double capacity = w.brake_capacity_nm + tire.rolling_resistance * r * w.load_n;
    double brake = stick;
    if (std::abs(stick) > capacity) brake = std::copysign(capacity, stick);
    w.brake_torque_nm = -brake;
    w.spin_radps += h * (other - brake) / inertia;
    if (std::abs(stick) <= capacity) w.spin_radps = 0;
  }
}

}  // namespace rig::model::vehicle
