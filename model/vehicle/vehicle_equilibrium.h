#pragma once
/// @file
/// The start in equilibrium (issue 12, part 4), shared by a single vehicle
/// (VehicleModel::settle) and a combination (CombinationShell::settle): the loop that relaxes
/// every state but the pose to its steady value, with the brakes holding at rest or with the
/// throttle found that holds a forward speed, the chassis's in-plane motion held after each step.
#include <algorithm>
#include <cmath>

#include "model/signals.h"

namespace rig::model::vehicle {

struct Equilibrium {
  double throttle = 0;          ///< the throttle that holds the speed (0 at rest) [0..1]
  double residual_ax_mps2 = 0;  ///< a_x left at that throttle (non-zero: throttle at a bound)
  int gear = 0;                 ///< the automatic's gear in it
};

inline constexpr double kSettleTimeS = 4.0;          // the slowest relaxation: the throttle
inline constexpr double kSettleMaxTimeS = 30.0;      // ... of a heavy truck (tau ~ 2 s)
inline constexpr double kSettledAxMps2 = 0.002;      // rolling: settled once |a_x| is below
inline constexpr double kThrottleGainPerMps2 = 0.8;  // d throttle/dt = -k a_x [1/(m/s^2 s)]
inline constexpr double kHoldingPressurePa = 1e7;    // at rest: brakes holding, every wheel

/// Steps `step(signals)` (false: the model failed, it starts as it is) for kSettleTimeS at step
/// h, rolling on up to kSettleMaxTimeS until |a_x| < kSettledAxMps2; after each step `hold()`
/// puts the in-plane motion back and `ax()` is the leading unit's a_x, integrated into the
/// throttle while rolling (the loop's time constant 1/(k da/dthrottle): ~0.3 s for the sedan,
/// ~2 s for the 40 t tractor-semitrailer, whose gain the sedan's drive train would not stand).
/// Allocation-free.
template <class Step, class Hold, class Ax>
Equilibrium settle_loop(double h, double speed_mps, int gear_request, Step step, Hold hold,
                        Ax ax) noexcept {
  const bool rolling = speed_mps != 0.0;
  Signals s{};  // the rest invalid: their fallbacks (no hand torque, no assist input)
  // the wheel held straight: a routed angle's robot would let go of an invalid one
  // (angle_from_input)
  s.set(Signal::kSteeringWheelAngleCmd, 0.0);
  s.set(Signal::kGearRequest, rolling ? gear_request : 0);
  s.set(Signal::kBrakePressureFront, rolling ? 0.0 : kHoldingPressurePa);
  s.set(Signal::kBrakePressureRear, rolling ? 0.0 : kHoldingPressurePa);
  Equilibrium e;
  const auto steps = static_cast<long>(std::lround(kSettleTimeS / h));
  const auto max_steps = static_cast<long>(std::lround(kSettleMaxTimeS / h));
  for (long k = 0; k < max_steps; ++k) {
    if (k >= steps && (!rolling || std::abs(e.residual_ax_mps2) < kSettledAxMps2)) break;
    s.set(Signal::kThrottlePedal, e.throttle);
    if (!step(s)) break;
    e.residual_ax_mps2 = ax();
    if (!rolling) continue;
    hold();
    e.throttle = std::clamp(e.throttle - kThrottleGainPerMps2 * e.residual_ax_mps2 * h, 0.0, 1.0);
  }
  return e;
}

}  // namespace rig::model::vehicle
