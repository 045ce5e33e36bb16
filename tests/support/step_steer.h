#pragma once
/// @file
/// The ISO 7401 step steer as the vehicle tests drive it: the steering-wheel angle command ramps
/// from 0 at t_step_s to sw_rad in 0.1 s (ISO 7401: as fast as possible, < 0.15 s), the throttle
/// holds the speed (0.2 + 0.5 (v0 - v), within [0, 1]); every other input as all_driver_inputs().

#include <algorithm>
#include <cmath>

#include "model/vehicle/vehicle_model.h"
#include "tests/support/driver_inputs.h"

namespace rig::test {

struct StepSteer {
  double sw_rad = 0.5;          ///< the steering-wheel angle of the step
  double speed_mps = 80 / 3.6;  ///< the speed held (and the start's)
  double t_step_s = 1.0;        ///< the ramp's start
  double duration_s = 6.0;
};

/// Runs the vehicle `p` at step size h through `maneuver`, calling observe(t, model, signals)
/// after each step (t: the step's start time). Returns false at the first step that fails or
/// leaves the yaw rate not finite (not observed), true at the end.
template <class Observe>
bool run_step_steer(const model::vehicle::VehicleParams& p, double h, const StepSteer& maneuver,
                    Observe&& observe) {
  using model::Signal;
  model::vehicle::VehicleModel m(p, h);
  model::Signals s = all_driver_inputs();
  m.set_forward_speed(maneuver.speed_mps);
  const long n = std::lround(maneuver.duration_s / h);
  for (long k = 0; k < n; ++k) {
    const double t = m.time_s();
    s[Signal::kSteeringWheelAngleCmd] =
        maneuver.sw_rad * std::clamp((t - maneuver.t_step_s) / 0.1, 0.0, 1.0);
    s[Signal::kThrottlePedal] =
        std::clamp(0.2 + 0.5 * (maneuver.speed_mps - s[Signal::kVehicleSpeed]), 0.0, 1.0);
    if (m.step(s) != model::StepStatus::kOk || !std::isfinite(s[Signal::kYawRate])) return false;
    observe(t, static_cast<const model::vehicle::VehicleModel&>(m),
            static_cast<const model::Signals&>(s));
  }
  return true;
}

}  // namespace rig::test
