#pragma once
/// @file
/// The enhanced steering model (Fig. 7 right, sec. 2.2): the steering system (any
/// SteeringSystem: its 2 coordinates, wheel angle and rack travel u) and one knuckle per steered
/// wheel in ONE mechanical block, coupled only by the compliant tie rods / drag links (F_S1,
/// F_S2), so that their stiff spring-damper and its partials are implicit in eq. (8).
/// A knuckle's coordinate is its steer about the steering axis expressed as rack-equivalent
/// travel u_k (VehicleState::rack_at_wheel_m: the eq. (29) tables are evaluated at it, gamma =
/// gamma(z, u_k)), its speed u_k' (VehicleState::knuckle_rate_mps). With gamma' = dgamma/du u_k'
/// (frozen at the step's pose) the knuckle's inertia Theta about the axis is the mass
/// Theta (dgamma/du)^2 on u_k, and the axis moment M (steering_axis_moment_nm, from the
/// wheel-spin stage's loads at the start of the step) the force M dgamma/du:
///   tie rod:  F_k = c (u - u_k) + d (u' - u_k')                (pulls the rack, pushes the
///   knuckle) rack:     q_u  = q_system,u - sum F_k knuckle:  Theta (dgamma/du)^2 u_k'' = M
///   dgamma/du + F_k
/// At a static hold F_k = -M dgamma/du: the simple model's quasi-static tie-rod force.

#include <array>

#include <Eigen/Core>

#include "model/solver/mechanical_block.h"
#include "model/solver/mechanical_stepper.h"
#include "model/solver/stage.h"
#include "model/vehicle/steering/steering_system.h"
#include "model/vehicle/vehicle_params.h"
#include "model/vehicle/vehicle_state.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle {

class EnhancedSteering final : public solver::MechanicalBlock<Eigen::Dynamic> {
 public:
  /// Sized 2 + the steered wheels (allocates; construction only).
  EnhancedSteering(const VehicleParams& p, SteeringSystem& system, VehicleState& state,
                   VehicleWorkspace& work);
  [[nodiscard]] Eigen::Index size() const noexcept override { return y_.size(); }
  [[nodiscard]] Vector& coordinates() noexcept override { return y_; }
  [[nodiscard]] Vector& speeds() noexcept override { return z_; }
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;
  /// The steering system's dry friction (SteeringSystem::dry_friction) on its two coordinates
  /// (wheel angle, rack travel: the first two), stick-predicted by the stepper.
  void dry_friction(const Vector& y, const Vector& z,
                    solver::FrictionSet<Eigen::Dynamic>& contacts) const noexcept override;

  /// Before the step: the state into y, z and each knuckle's axis moment at the step's start.
  void gather() noexcept;
  /// After the step: y, z back into the state; the tie-rod forces at the new state into the
  /// workspace (WheelWork::tie_rod_force_n).
  void scatter() noexcept;
  [[nodiscard]] int knuckle_count() const noexcept { return knuckles_; }
  /// The wheel index of knuckle j.
  [[nodiscard]] int wheel_of(int j) const noexcept { return wheel_[static_cast<std::size_t>(j)]; }
  /// F_k = c (u - u_k) + d (u' - u_k') of knuckle j at (y, z) [N].
  [[nodiscard]] double tie_rod_force_n(const Vector& y, const Vector& z, int j) const noexcept;

 private:
  const VehicleParams& p_;
  SteeringSystem& system_;
  VehicleState& state_;
  VehicleWorkspace& work_;
  int knuckles_ = 0;
  std::array<int, kMaxWheels> wheel_{};
  std::array<double, kMaxWheels> axis_moment_nm_{};  ///< at the step's start
  Vector y_, z_;
};

/// The enhanced block's stage in the sequence: gather, eq. (8) (dense LU of 2 + n), scatter.
class EnhancedSteeringStage final : public solver::Stage {
 public:
  explicit EnhancedSteeringStage(EnhancedSteering& block) : block_(block), stepper_(block) {}
  void advance(double h) noexcept override {
    block_.gather();
    stepper_.advance(h);
    block_.scatter();
  }

 private:
  EnhancedSteering& block_;
  solver::MechanicalStepper<Eigen::Dynamic> stepper_;
};

}  // namespace rig::model::vehicle
