#pragma once
/// @file
/// What a free body of N DOF on its mounts (FreeBody: 6, Seat: 1) shares: its parameters, the
/// road (gravity), the vehicle state that holds its coordinates and the chassis', the workspace
/// (lookahead, engine torque), its slot, and the chassis pose its block sees.

#include "model/road/road.h"
#include "model/solver/mechanical_block.h"
#include "model/vehicle/free_body/input_key.h"
#include "model/vehicle/free_body/mount.h"
#include "model/vehicle/vehicle_state.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle {

template <int N>
class MountedBody : public solver::MechanicalBlock<N> {
 public:
  [[nodiscard]] const FreeBodyParams& params() const noexcept { return p_; }

 protected:
  /// p, road, state and work must outlive the body; slot: its index in the state's arrays.
  MountedBody(const FreeBodyParams& p, const road::Road& road, VehicleState& state,
              const VehicleWorkspace& work, int slot) noexcept
      : p_(p), road_(road), state_(state), work_(work), slot_(slot) {}

  /// What chassis_pose() is computed from: the chassis' coordinates and speeds, the lookahead.
  using ChassisInputs = std::array<double, 13>;
  [[nodiscard]] ChassisInputs chassis_inputs() const noexcept {
    ChassisInputs in;
    std::size_t at = put(in, 0, state_.framework_y.data(), 6);
    at = put(in, at, state_.framework_z.data(), 6);
    in[at] = work_.lookahead_s;
    return in;
  }
  /// The chassis where the framework will be when the body's predicted coordinates are (eq. 6:
  /// the step's lookahead, VehicleWorkspace::lookahead_s); computed once per chassis state.
  [[nodiscard]] const RigidPose& chassis_pose() const noexcept {
    if (!chassis_key_.hit(chassis_inputs()))
      chassis_ = predicted_pose(state_.framework_y, state_.framework_z, work_.lookahead_s);
    return chassis_;
  }
  [[nodiscard]] std::size_t slot() const noexcept { return static_cast<std::size_t>(slot_); }

  const FreeBodyParams& p_;
  const road::Road& road_;
  VehicleState& state_;
  const VehicleWorkspace& work_;
  int slot_;

 private:
  mutable InputKey<13> chassis_key_;  // per-step caches: const queries, one thread per unit
  mutable RigidPose chassis_;
};

}  // namespace rig::model::vehicle
