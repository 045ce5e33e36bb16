#pragma once
/// @file
/// What the drive train and the wheel spins ask of the shafts between the differential input
/// (the carrier, w_c) and the driven wheels: HalfShafts (open differentials, every driven wheel
/// the same torque) or differential::DifferentialShafts (a configured tree of differentials).

#include <array>

#include "model/vehicle/vehicle_state.h"

namespace rig::model::vehicle {

class DrivenShafts {
 public:
  DrivenShafts() = default;
  DrivenShafts(const DrivenShafts&) = delete;
  DrivenShafts& operator=(const DrivenShafts&) = delete;
  virtual ~DrivenShafts() = default;

  /// How many driven wheels, and wheel i of them (front to rear, left before right).
  [[nodiscard]] virtual int count() const noexcept = 0;
  [[nodiscard]] virtual int wheel(int i) const noexcept = 0;
  /// Every driven wheel's shaft torque T (indexed by wheel) at the state's twists and wheel spins
  /// and the carrier speed, and what the wheel's implicit spin step adds to its inertia,
  /// -h dT/dw of its own spin (>= 0) [kg m^2].
  virtual void wheel_torques(double carrier_radps, double h,
                             std::array<double, kMaxWheels>& torque_nm,
                             std::array<double, kMaxWheels>& added_inertia_kgm2) const noexcept = 0;
  /// The torque the shafts load the carrier with: the sum of the shaft torques.
  [[nodiscard]] virtual double carrier_torque_nm(double carrier_radps) const noexcept = 0;
};

}  // namespace rig::model::vehicle
