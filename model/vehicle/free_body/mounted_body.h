#pragma once
/// @file
/// What a free body of N DOF on its mounts (FreeBody: 6, Seat: 1) shares: its parameters, the
/// road (gravity), the vehicle state that holds its coordinates and the chassis', the workspace
/// (lookahead, engine torque), its slot, and the chassis pose its block sees.

#include "model/road/road.h"
#include "model/solver/mechanical_block.h"
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

  /// The chassis where the framework will be when the body's predicted coordinates are (eq. 6:
  /// the step's lookahead, VehicleWorkspace::lookahead_s).
  [[nodiscard]] RigidPose chassis_pose() const noexcept {
    return predicted_pose(state_.framework_y, state_.framework_z, work_.lookahead_s);
  }
  [[nodiscard]] std::size_t slot() const noexcept { return static_cast<std::size_t>(slot_); }

  const FreeBodyParams& p_;
  const road::Road& road_;
  VehicleState& state_;
  const VehicleWorkspace& work_;
  int slot_;
};

}  // namespace rig::model::vehicle
