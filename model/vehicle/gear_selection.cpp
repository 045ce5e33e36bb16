#include "model/vehicle/gear_selection.h"

#include <algorithm>
#include <cmath>

namespace rig::model::vehicle {
namespace {

double ratio_of(const DrivetrainParams& d, int gear) noexcept {
  return d.gear_ratios[static_cast<std::size_t>(gear - 1)] * d.final_drive_ratio;
}

/// The shift schedule: up above the throttle-dependent point, down when the lower gear stays
/// below twice the downshift speed and the turbine falls below it; not within the dwell time.
int automatic_gear(const DrivetrainParams& d, const VehicleInputs& in, double carrier_radps,
                   const VehicleState& state) noexcept {
  const int top = static_cast<int>(d.gear_ratios.size());
  int gear = state.gear;
  if (gear < 1) gear = 1;
  const double turbine = ratio_of(d, gear) * carrier_radps;
  const double up = d.upshift_speed_low_radps +
                    in.throttle * (d.upshift_speed_high_radps - d.upshift_speed_low_radps);
  if (state.time_s - state.last_shift_s >= d.shift_dwell_s) {
    if (turbine > up && gear < top)
      ++gear;
    else if (gear > 1) {
      const double lower = ratio_of(d, gear - 1) * carrier_radps;
      if (lower < d.downshift_speed_radps * 2.0 && turbine < d.downshift_speed_radps) --gear;
    }
  }
  return gear;
}

}  // namespace

double select_gear(const DrivetrainParams& d, const VehicleInputs& in, double carrier_speed_radps,
                   VehicleState& state) noexcept {
  const int top = static_cast<int>(d.gear_ratios.size());
  const int gear = in.gear_request != 99 ? std::clamp(in.gear_request, -1, top)
                                         : automatic_gear(d, in, carrier_speed_radps, state);
  if (gear != state.gear) state.last_shift_s = state.time_s;
  state.gear = gear;
  if (gear > 0) return ratio_of(d, gear);
  if (gear < 0) return -d.reverse_ratio * d.final_drive_ratio;
  return 0;
}

int gear_for_speed(const DrivetrainParams& d, double carrier_speed_radps) noexcept {
  const int top = static_cast<int>(d.gear_ratios.size());
  int gear = 1;
  while (gear < top &&
         ratio_of(d, gear) * std::abs(carrier_speed_radps) > d.upshift_speed_low_radps)
    ++gear;
  return gear;
}

}  // namespace rig::model::vehicle
