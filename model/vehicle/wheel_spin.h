#pragma once
/// @file
/// The wheel spin rates as a subsystem stage with brakes as implicit dry friction
/// (method.md sec. 6): per wheel, Theta w' = T_shaft - r_D F_x - T_B. The stage predicts the
/// brake (+ rolling resistance) torque that brings w to zero at t + h; if it is within the
/// capacity it applies exactly that (the wheel sticks: no creep, no chatter), otherwise the
/// capacity against the motion. The tire's damping path d_x and the shaft damping enter the
/// implicit mass Theta - h dq/dw. Also the tie-rod linkage: wheel steer from the new rack
/// travel through the compliant tie rods (quasi-static).

#include <array>

#include "model/solver/stage.h"
#include "model/vehicle/driven_shafts.h"
#include "model/vehicle/drivetrain.h"

namespace rig::model::vehicle {

/// The moment about a steered wheel's steering axis at the step's start (steering_axis.h) from
/// its tire's loads: the lateral force of the last step, the load and the aligning torque of the
/// contact. Both steering models take it: the simple one through the tie rods at the rack, the
/// enhanced one on the knuckle (EnhancedSteering).
[[nodiscard]] double wheel_steering_axis_moment_nm(const VehicleParams& p,
                                                   const VehicleState& state, const WheelWork& w,
                                                   int wheel) noexcept;

class WheelSpinStage final : public solver::Stage {
 public:
  /// Advances state.spin_radps and state.rack_at_wheel_m; writes the wheels' orientation,
  /// tie-rod, shaft and brake torques and the rack force into the workspace.
  WheelSpinStage(const VehicleParams& p, VehicleState& state, const VehicleInputs& inputs,
                 VehicleWorkspace& work, const DrivenShafts* shafts, const Drivetrain& drivetrain);
  void advance(double h) noexcept override;

 private:
  void tie_rods(double h) noexcept;

  const VehicleParams& p_;
  VehicleState& state_;
  const VehicleInputs& inputs_;
  VehicleWorkspace& work_;
  std::array<bool, kMaxWheels> driven_{};
  const DrivenShafts* shafts_;
  std::array<double, kMaxWheels> shaft_torque_nm_{};  ///< the step's, per wheel (workspace)
  std::array<double, kMaxWheels> shaft_inertia_kgm2_{};
  const Drivetrain& drivetrain_;
};

}  // namespace rig::model::vehicle
