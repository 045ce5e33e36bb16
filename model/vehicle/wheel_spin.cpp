#include "model/vehicle/wheel_spin.h"

#include <cmath>

#include "model/tire/tmeasy_bore.h"
#include "model/tire/tmeasy_tire.h"
#include "model/vehicle/steering/steering_axis.h"

namespace rig::model::vehicle {

WheelSpinStage::WheelSpinStage(const VehicleParams& p, VehicleState& state,
                               const VehicleInputs& inputs, VehicleWorkspace& work,
                               const DrivenShafts* shafts, const Drivetrain& drivetrain)
    : p_(p), state_(state), inputs_(inputs), work_(work), shafts_(shafts), drivetrain_(drivetrain) {
  if (shafts_ != nullptr) {
    for (int i = 0; i < shafts_->count(); ++i)
      driven_[static_cast<std::size_t>(shafts_->wheel(i))] = true;
  }
}

double wheel_steering_axis_moment_nm(const VehicleParams& p, const VehicleState& state,
                                     const WheelWork& w, int wheel) noexcept {
  const auto k = static_cast<std::size_t>(wheel);
  const AxleParams& axle = p.axles[k / 2];
  // aligning torque M_z = -(n(s_y) + caster trail) F_y: TMeasy's pneumatic trail n falls with
  // the lateral slip (Rill 2011, sec. 3.4.3), so the steering goes light near the limit; F_x,
  // the shaft torque and F_y of the last step, the bore torque of the newest patch twist
  SteeringAxisLoads loads;
  loads.lat_force_n = state.lateral_force_n[k];
  loads.long_force_n = state.long_force_n[k];
  loads.shaft_torque_nm = state.shaft_torque_nm[k];
  loads.wheel_radius_m = w.tire.kinematics.rolling_radius_m;
  loads.load_n = w.load_n;
  loads.aligning_nm =
      tire::aligning_torque_nm(axle.tire.tmeasy, w.tire.kinematics, w.load_n, loads.lat_force_n);
  loads.bore_nm = state.bore_torque_nm[k];
  const int side = (k % 2 == 0) ? 1 : -1;
  return steering_axis_moment_nm(axle, loads, w.steer_kinematic_rad, side);
}

void WheelSpinStage::tie_rods(double h) noexcept {
  // Tie-rod linkage from the new rack travel; the wheel's steer is gamma(z, u) of the kinematic
  // tables (SuspensionKinematics, eq. 29) at the rack travel at the wheel.
  const double rack = state_.steering_y(1);
  const SteeringParams& sp = p_.steering;
  const bool enhanced = sp.model == SteeringModel::kEnhanced;
  double rack_force = 0;
  double bore_stiffness = 0;
  int first_steered = -1;  // the first steered axle's left wheel (F_S1, F_S2 in the report)
  for (int i = 0; i < work_.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    WheelWork& w = work_.wheels[k];
    const AxleParams& axle = p_.axles[k / 2];
    if (!axle.steered) continue;
    if (axle.tire.tmeasy.bore.enabled) {
      // the bore torque: the patch twists with the wheel's turn about the normal (steer rate
      // from the new rack speed, or the knuckle's, + yaw rate) and relaxes as it rolls
      // (model/tire/tmeasy_bore.h)
      const double steer_speed_mps = enhanced ? state_.knuckle_rate_mps[k] : state_.steering_z(1);
      const double turn_radps = w.steer_d_du * steer_speed_mps + state_.framework_z(5);
      const tire::TireKinematics& kin = w.tire.kinematics;
      const tire::BoreStep bore = tire::bore_step(
          axle.tire.tmeasy, state_.bore_twist_rad[k], turn_radps,
          kin.rolling_radius_m * std::abs(kin.spin_radps), w.load_n, w.road_friction, h);
      state_.bore_twist_rad[k] = bore.twist_rad;
      state_.bore_torque_nm[k] = bore.torque_nm;
      // simple model: at the rack through dgamma/du, in series with the tie rod
      const double at_rack = bore.stiffness_nmprad * w.steer_d_du * w.steer_d_du;
      if (!enhanced && at_rack > 0)
        bore_stiffness += at_rack * sp.tie_rod_stiffness_npm / (at_rack + sp.tie_rod_stiffness_npm);
    }
    if (!enhanced) {
      // simple model: quasi-static compliance, the axis moment loads the rack by virtual work,
      // F_rack = -M dgamma/du (eq. 29)
      w.tie_rod_force_n = -wheel_steering_axis_moment_nm(p_, state_, w, i) * w.steer_d_du;
      state_.rack_at_wheel_m[k] = rack - w.tie_rod_force_n / sp.tie_rod_stiffness_npm;
    }
    // (enhanced: EnhancedSteering has advanced the knuckle's rack_at_wheel_m and written the
    // tie rod's spring-damper force; it takes this bore torque at the next step's start)
    // gamma of eq. (29) at the new rack travel at the wheel, linear in u about the step's pose
    set_wheel_orientation(
        w, w.steer_kinematic_rad + w.steer_d_du * (state_.rack_at_wheel_m[k] - w.steer_at_rack_m),
        w.camber_rad);
    rack_force += w.tie_rod_force_n;
    if (first_steered < 0) first_steered = i;
  }
  work_.rack_force_n = rack_force;
  work_.rack_bore_stiffness_npm = bore_stiffness;
  work_.rack_force_at_m = rack;
  if (first_steered >= 0) {
    work_.tie_rod_force_left_n =
        work_.wheels[static_cast<std::size_t>(first_steered)].tie_rod_force_n;
    work_.tie_rod_force_right_n =
        work_.wheels[static_cast<std::size_t>(first_steered) + 1].tie_rod_force_n;
  }
}

void WheelSpinStage::advance(double h) noexcept {
  tie_rods(h);
  work_.carrier_speed_radps = drivetrain_.carrier_speed_radps();  // newest (eq. 8 order)
  if (shafts_ != nullptr)
    shafts_->wheel_torques(work_.carrier_speed_radps, h, shaft_torque_nm_, shaft_inertia_kgm2_);
  for (int i = 0; i < work_.wheel_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    WheelWork& w = work_.wheels[k];
    const AxleParams& axle = p_.axles[k / 2];
    const tire::TmeasyParams& tire = axle.tire.tmeasy;
    const tire::TireContact& contact = w.tire;
    const double r = contact.kinematics.rolling_radius_m;
    // F_x on the spin with the new deflection (limited as on the contact, eq. 26) and dF_x/dw
    // through the damping path (eq. 24, at the f of the start of the step)
    const tire::SpinForce fx = tire::spin_force(tire, contact, state_.tire_deflection_m[k]);
    double inertia = axle.tire.spin_inertia_kgm2 + h * r * fx.d_force_d_spin;
    const double ts = driven_[k] ? shaft_torque_nm_[k] : 0.0;
    if (driven_[k]) inertia += shaft_inertia_kgm2_[k];
    w.shaft_torque_nm = ts;
    const double other = ts - r * fx.long_force_n;
    // Stick prediction: the friction torque that makes w(k+1) = 0.
    double& spin = state_.spin_radps[k];
    const double stick = other + inertia * spin / h;
    const double capacity = axle.brake_gain_nm_per_pa * inputs_.brake_pressure_pa[k] +
                            tire::rolling_resistance_torque_nm(tire, w.load_n, r);
    double brake = stick;
    if (std::abs(stick) > capacity) brake = std::copysign(capacity, stick);
    w.brake_torque_nm = -brake;
    spin += h * (other - brake) / inertia;
    if (std::abs(stick) <= capacity) spin = 0;
  }
}

}  // namespace rig::model::vehicle
