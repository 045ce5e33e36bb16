// VehicleModel::settle: the start in equilibrium (issue 12, part 4). A run that begins from the
// design position (hub travels 0, tires undeflected, wheels at v/r) starts with a transient the
// ECU sees first; instead every state but the pose is relaxed to its steady value first (the
// loop: vehicle_equilibrium.h, shared with the combinations).
#include "model/vehicle/vehicle_equilibrium.h"

#include "model/vehicle/vehicle_model.h"

namespace rig::model::vehicle {

VehicleModel::Pose VehicleModel::begin_settle(double speed_mps) noexcept {
  const Pose pose{state_.framework_y(0), state_.framework_y(1), state_.framework_y(3)};
  if (speed_mps != 0.0) set_forward_speed(speed_mps);
  return pose;
}

void VehicleModel::hold_plane_motion(double speed_mps, double lateral_mps) noexcept {
  const Vec6 old_y = state_.framework_y.head<6>(), old_z = state_.framework_z.head<6>();
  state_.framework_z(0) = speed_mps;
  state_.framework_z(1) = lateral_mps;
  state_.framework_z(5) = 0;
  carry_free_bodies(p_, old_y, old_z, state_);  // the bodies move with the chassis
}

void VehicleModel::end_settle(const Pose& pose, double speed_mps) noexcept {
  // back at the pose, clock at 0 (the gearbox's dwell clock moves with it), motion as held
  const double settled_s = state_.time_s;
  state_.time_s = 0;
  state_.last_shift_s -= settled_s;
  const Vec6 old_y = state_.framework_y.head<6>(), old_z = state_.framework_z.head<6>();
  state_.framework_y(0) = pose.x_m;
  state_.framework_y(1) = pose.y_m;
  state_.framework_y(3) = pose.yaw_rad;
  carry_free_bodies(p_, old_y, old_z, state_);
  hold_plane_motion(speed_mps);
  state_.acceleration_mps2.setZero();
  saved_ = state_;
  blocks_->update_contacts(0.0);
  blocks_->update_outputs();
}

Equilibrium VehicleModel::settle(double speed_mps, int gear_request) noexcept {
  const Pose pose = begin_settle(speed_mps);
  // On a surface the vehicle rolls in place (as on a drum): its x, y held at the pose, so that
  // it settles on the road where it starts (it would otherwise settle some ten metres on).
  const bool in_place = static_cast<bool>(p_.road.surface);
  Equilibrium e = settle_loop(
      h_, speed_mps, gear_request, [&](Signals& s) { return step(s) == StepStatus::kOk; },
      [&] {
        hold_plane_motion(speed_mps);
        if (!in_place) return;
        const Vec6 old_y = state_.framework_y.head<6>(), old_z = state_.framework_z.head<6>();
        state_.framework_y(0) = pose.x_m;
        state_.framework_y(1) = pose.y_m;
        carry_free_bodies(p_, old_y, old_z, state_);
      },
      [&] { return state_.acceleration_mps2.x(); });
  end_settle(pose, speed_mps);
  e.gear = state_.gear;
  return e;
}

}  // namespace rig::model::vehicle
