#pragma once
/// @file
/// The kinematic functions of eq. (29) for every wheel of the vehicle (method.md sec. 2 and 6):
/// wheel-centre x, y, alpha, beta, gamma of hub travel z and rack travel u, as model/kinematics
/// tables (given in AxleKinematicsParams, or generated from its simple geometry), the right wheel
/// mirrored from the left. Evaluated once per wheel and step at y_V(k) (K and M are frozen over
/// the step, eqs. 5-7); the framework then moves the wheel centre along the tangent
/// (dx/dz, dy/dz, 1) of the table, and the wheel-spin stage linearizes gamma in u.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "model/kinematics/wheel_kinematics.h"
#include "model/vehicle/vehicle_params.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle {

/// The generator's geometry for an axle's left wheel: the AxleKinematicsParams geometry, offsets
/// relative to the design position, steer asin(u / arm) on a steered axle.
[[nodiscard]] kinematics::SuspensionGeometry left_wheel_geometry(const AxleParams& axle,
                                                                 const SteeringParams& steering);

/// The grid of generated tables: hub travel from 2 cm beyond the rebound stop to 2 cm beyond the
/// bump stop in 1 cm steps; rack travel +-0.9 steering arm in 21 nodes (steered axle) or none.
[[nodiscard]] kinematics::Grid2D generated_grid(const AxleParams& axle,
                                                const SteeringParams& steering);

class SuspensionKinematics {
 public:
  /// Builds the tables of every wheel (allocates). Throws std::invalid_argument on given tables
  /// that do not match their grid or whose rack-travel grid is not symmetric about 0.
  explicit SuspensionKinematics(const VehicleParams& p);

  /// Eq. (29) of wheel i at hub travel z and rack travel u at the wheel.
  [[nodiscard]] kinematics::WheelPose pose(int wheel, double hub_travel_m,
                                           double rack_travel_m) const noexcept;

  /// Evaluates every wheel at the hub travel of the framework coordinates y = [body(6), s_i] and
  /// the rack travel at the wheel of the last step (VehicleState::rack_at_wheel_m) and writes the
  /// pose into the workspace: hub offsets and tangent, camber, steer (gamma) and dgamma/du.
  void update(const VehicleState& state, VehicleWorkspace& work) const noexcept;

 private:
  std::vector<kinematics::WheelKinematics> wheels_;
  /// Which of x, y, alpha, gamma of each wheel has a non-zero node (beta is not used by the
  /// framework): identically zero tables are not interpolated (an unsteered axle with the zero
  /// geometry costs nothing; the hub then moves along body z).
  struct Used {
    bool x = false, y = false, alpha = false, gamma = false;
  };
  std::array<Used, kMaxWheels> used_{};
  /// A wheel of a rigid axle (rigid_axle.h): its hub travel comes from the axle's heave and roll,
  /// its camber is the axle's roll and its steer gets roll steer; the tables give gamma only.
  struct Rigid {
    bool rigid = false;
    double half_track_m = 0;
    double roll_steer = 0;
  };
  std::array<Rigid, kMaxWheels> rigid_{};
  void update_rigid_wheel(int i, const VehicleState& state, WheelWork& w) const noexcept;
};

}  // namespace rig::model::vehicle
