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

/// The chassis where the framework will be when the free bodies' predicted coordinates are
/// (eq. 6: the step's lookahead, VehicleWorkspace::lookahead_s): one per vehicle, shared by its
/// free bodies (FreeBodies), computed once per chassis state.
class PredictedChassis {
 public:
  /// state and work must outlive it.
  PredictedChassis(const VehicleState& state, const VehicleWorkspace& work) noexcept
      : state_(state), work_(work) {}

  [[nodiscard]] const RigidPose& pose() const noexcept {
    if (!key_.hit(inputs()))
      pose_ = predicted_pose(state_.framework_y, state_.framework_z, work_.lookahead_s);
    return pose_;
  }

  /// What pose() is computed from: the chassis' coordinates and speeds, the lookahead.
  using Inputs = std::array<double, 13>;
  [[nodiscard]] Inputs inputs() const noexcept {
    Inputs in;
    std::size_t at = put(in, 0, state_.framework_y.data(), 6);
    at = put(in, at, state_.framework_z.data(), 6);
    in[at] = work_.lookahead_s;
    return in;
  }

 private:
  const VehicleState& state_;
  const VehicleWorkspace& work_;
  mutable InputKey<13> key_;  // a per-step cache: const queries, one thread per unit
  mutable RigidPose pose_;
};

template <int N>
class MountedBody : public solver::MechanicalBlock<N> {
 public:
  [[nodiscard]] const FreeBodyParams& params() const noexcept { return p_; }

 protected:
  /// p, road, state, work and chassis must outlive the body; slot: its index in the state's
  /// arrays; chassis: the vehicle's predicted chassis, shared by its free bodies.
  MountedBody(const FreeBodyParams& p, const road::Road& road, VehicleState& state,
              const VehicleWorkspace& work, int slot, const PredictedChassis& chassis) noexcept
      : p_(p), road_(road), state_(state), work_(work), slot_(slot), chassis_(chassis) {}

  [[nodiscard]] const RigidPose& chassis_pose() const noexcept { return chassis_.pose(); }
  using ChassisInputs = PredictedChassis::Inputs;
  [[nodiscard]] ChassisInputs chassis_inputs() const noexcept { return chassis_.inputs(); }
  [[nodiscard]] std::size_t slot() const noexcept { return static_cast<std::size_t>(slot_); }

  const FreeBodyParams& p_;
  const road::Road& road_;
  VehicleState& state_;
  const VehicleWorkspace& work_;
  int slot_;

 private:
  const PredictedChassis& chassis_;
};

}  // namespace rig::model::vehicle
