#pragma once
/// @file
/// Torsionally compliant half shafts behind open differentials, as a force element (eq. 3).
/// With open differentials throughout (and a 50:50 centre differential for all-wheel drive),
/// every driven wheel gets the same shaft torque T and the side-gear speeds average to the
/// differential input speed w_c. With twists theta_i and T = c theta_i + d theta_i':
///   T = (c sum theta + d (n w_c - sum w_i)) / n,   theta_i' = (T - c theta_i) / d.
/// Linear in theta, so its Jacobian is exact; integrated implicitly the torques stay smooth.

#include <array>

#include "model/solver/force_element.h"
#include "model/vehicle/driven_shafts.h"
#include "model/vehicle/vehicle_state.h"
#include "model/vehicle/vehicle_workspace.h"

namespace rig::model::vehicle {

class HalfShafts final : public solver::ForceElement<Eigen::Dynamic>, public DrivenShafts {
 public:
  /// @param driven_wheels indices of the driven wheels (at least one); the twists are
  /// state.shaft_twist_rad, the wheel spins state.spin_radps, the carrier speed the workspace's.
  HalfShafts(const DrivetrainParams& p, VehicleState& state, const VehicleWorkspace& work,
             const std::array<int, kMaxWheels>& driven_wheels, int driven_count);
  [[nodiscard]] Eigen::Index state_size() const noexcept override { return n_; }
  [[nodiscard]] Vector& state() noexcept override { return state_.shaft_twist_rad; }
  [[nodiscard]] const Vector& state_const() const noexcept { return state_.shaft_twist_rad; }
  void rate(const Vector& s, Vector& f) const noexcept override;
  bool rate_jacobian(const Vector& s, Matrix& df_ds) const noexcept override;
  /// The common shaft torque T at twists s, carrier speed w_c and the wheel spins of the state.
  [[nodiscard]] double shaft_torque_nm(const Vector& s, double carrier_radps) const noexcept;
  /// dT / d w_c and dT / d w_i.
  [[nodiscard]] double d_torque_d_carrier() const noexcept { return d_; }
  [[nodiscard]] double d_torque_d_wheel() const noexcept { return -d_ / static_cast<double>(n_); }
  [[nodiscard]] int count() const noexcept override { return static_cast<int>(n_); }
  [[nodiscard]] int wheel(int i) const noexcept override {
    return wheels_[static_cast<std::size_t>(i)];
  }
  /// Every driven wheel the common torque, and h d / n.
  void wheel_torques(double carrier_radps, double h, std::array<double, kMaxWheels>& torque_nm,
                     std::array<double, kMaxWheels>& added_inertia_kgm2) const noexcept override;
  [[nodiscard]] double carrier_torque_nm(double carrier_radps) const noexcept override {
    return count() * shaft_torque_nm(state_const(), carrier_radps);
  }

 private:
  VehicleState& state_;
  const VehicleWorkspace& work_;
  double c_;
  double d_;
  std::array<int, kMaxWheels> wheels_;
  Eigen::Index n_;
};

}  // namespace rig::model::vehicle
