#pragma once
/// @file
/// ISO 7401 (lateral transient response, step input) measures of a recorded step response:
/// the response y (yaw rate, lateral acceleration) to the input x (steering-wheel angle) over a
/// window that starts before the step and ends in the steady state.
///
///   time reference t_0   the instant x reaches 50 % of its change (x_0 + 0.5 (x_ss - x_0));
///   response time        from t_0 until y first reaches 90 % of its change (`fraction`);
///   peak response time   from t_0 until y peaks (the largest change in the steady state's
///                        direction);
///   overshoot            (y_peak - y_ss) / (y_ss - y_0), a ratio (x 100: per cent);
///   steady-state gain    (y_ss - y_0) / (x_ss - x_0).
///
/// x_0, y_0 are the window's first samples; x_ss, y_ss the means over its last `steady_s`.
/// Crossings are interpolated linearly between samples; the peak is a sample's. NaN when the
/// series has no answer (no change of x or y, no crossing).

#include <span>

namespace rig::kpi {

struct StepResponse {
  double response_time_s;
  double peak_response_time_s;
  double overshoot;
  double steady_gain;
};

StepResponse step_response(std::span<const double> t_s, std::span<const double> y,
                           std::span<const double> x, double steady_s, double fraction);

}  // namespace rig::kpi
