#pragma once
/// @file
/// The driver's seat (1 DOF): the driver's mass on a vertical spring, damper and stops above a
/// chassis point. Coordinate: the mass's height (road frame z), speed its rate; it moves with
/// the chassis point horizontally. Deflection e = z - z_point (road z): at e = 0 the spring is
/// unloaded. The reaction acts on the chassis at the point, along road z.

#include <Eigen/Core>

#include "model/vehicle/free_body/free_body.h"
#include "model/vehicle/free_body/mounted_body.h"

namespace rig::model::vehicle {

class Seat final : public MountedBody<1> {
 public:
  /// Its coordinate is state.seat_y[slot], its speed state.seat_z[slot].
  Seat(const FreeBodyParams& p, const road::Road& road, VehicleState& state,
       const VehicleWorkspace& work, int slot, const PredictedChassis& chassis);

  [[nodiscard]] Eigen::Index size() const noexcept override { return 1; }
  [[nodiscard]] Vector& coordinates() noexcept override;
  [[nodiscard]] Vector& speeds() noexcept override;
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;

  /// Spring + damper + stop force on the driver's mass (up +) at (e, e').
  [[nodiscard]] double suspension_force_n(double e_m, double e_rate_mps) const noexcept;
  /// Deflection e and its rate at the chassis pose and the seat's state.
  [[nodiscard]] Eigen::Vector2d deflection(const RigidPose& chassis) const noexcept;
  /// The reaction on the chassis' 6 speeds at pose `chassis`.
  [[nodiscard]] Vec6 chassis_load(const RigidPose& chassis) const noexcept;
  [[nodiscard]] double beyond_stop_m(const RigidPose& chassis) const noexcept;

 private:
  [[nodiscard]] Eigen::Vector2d point_height(const RigidPose& chassis) const noexcept;
  Vec3 point_ = Vec3::Zero();  ///< chassis axes
  double k_ = 0, c_ = 0, clearance_ = 0, stop_k_ = 0;
};

}  // namespace rig::model::vehicle
