// VehicleModel::settle: the start in equilibrium (issue 12, part 4). A run that begins from the
// design position (hub travels 0, tires undeflected, wheels at v/r) starts with a transient the
// ECU sees first; instead every state but the pose is relaxed to its steady value first.
#include <algorithm>
#include <cmath>

#include "model/vehicle/vehicle_model.h"

namespace rig::model::vehicle {
namespace {

constexpr double kSettleTimeS = 4.0;          // the slowest relaxation: the integral throttle
constexpr double kThrottleGainPerMps2 = 0.8;  // d throttle/dt = -k a_x [1/(m/s^2 s)]
constexpr double kHoldingPressurePa = 1e7;    // at rest: brakes holding, every wheel

/// The chassis's in-plane motion held: forward speed v, no lateral speed, no yaw rate (heave,
/// pitch and roll settle freely).
void hold_plane_motion(VehicleState& s, double speed_mps) noexcept {
  s.framework_z(0) = speed_mps;
  s.framework_z(1) = 0;
  s.framework_z(5) = 0;
}

}  // namespace

VehicleModel::Equilibrium VehicleModel::settle(double speed_mps, int gear_request) noexcept {
  const double x = state_.framework_y(0), y = state_.framework_y(1), yaw = state_.framework_y(3);
  const bool rolling = speed_mps != 0.0;
  if (rolling) set_forward_speed(speed_mps);
  Signals s{};  // the rest invalid: their fallbacks (no steering input, no assist input)
  s.set(Signal::kGearRequest, rolling ? gear_request : 0);
  s.set(Signal::kBrakePressureFront, rolling ? 0.0 : kHoldingPressurePa);
  s.set(Signal::kBrakePressureRear, rolling ? 0.0 : kHoldingPressurePa);
  Equilibrium e;
  const auto steps = static_cast<long>(std::lround(kSettleTimeS / h_));
  for (long k = 0; k < steps; ++k) {
    s.set(Signal::kThrottlePedal, e.throttle);
    if (step(s) != StepStatus::kOk) break;  // a vehicle that cannot settle starts as it is
    e.residual_ax_mps2 = state_.acceleration_mps2.x();
    if (rolling) {
      hold_plane_motion(state_, speed_mps);
      e.throttle =
          std::clamp(e.throttle - kThrottleGainPerMps2 * e.residual_ax_mps2 * h_, 0.0, 1.0);
    }
  }
  // back at the pose, clock at 0 (the gearbox's dwell clock moves with it), motion as held
  const double settled_s = state_.time_s;
  state_.time_s = 0;
  state_.last_shift_s -= settled_s;
  state_.framework_y(0) = x;
  state_.framework_y(1) = y;
  state_.framework_y(3) = yaw;
  hold_plane_motion(state_, speed_mps);
  state_.acceleration_mps2.setZero();
  e.gear = state_.gear;
  saved_ = state_;
  blocks_->update_contacts();
  blocks_->update_outputs();
  return e;
}

}  // namespace rig::model::vehicle
