#pragma once
/// @file
/// Straight-line braking measures of a recorded speed v(t) from the brake point on: the first
/// sample at which the trigger (a brake pressure) reaches `threshold`, or the window's start
/// without a trigger. Distances are the trapezoidal integral of |v| (exact for a linear v).
///
///   braking distance     from the brake point until |v| falls to `stop_mps`;
///   mean deceleration    the mean fully developed deceleration of UN ECE R13-H (Annex 3):
///                        d_m = (v_b^2 - v_e^2) / (2 (s_e - s_b)), v_b = 0.8 v_0, v_e = 0.1 v_0,
///                        v_0 = |v| at the brake point, s_b and s_e the distances from the brake
///                        point at which |v| falls to v_b and v_e (the regulation's 25.92 =
///                        2 x 3.6^2 is this formula in km/h and m).
///
/// Crossings are interpolated linearly between samples. NaN when the series has no answer (no
/// brake point, |v| never falls that far).

#include <cstddef>
#include <optional>
#include <span>

namespace rig::kpi {

/// The first sample with trigger >= threshold (no trigger: 0); nullopt if there is none.
std::optional<std::size_t> brake_point(std::span<const double> trigger, double threshold,
                                       std::size_t samples);

/// From sample `from` (the brake point) until |v| <= stop_mps [m].
double braking_distance(std::span<const double> t_s, std::span<const double> v, std::size_t from,
                        double stop_mps);

/// The mean fully developed deceleration from sample `from` [m/s^2], > 0 when braking.
double mean_deceleration(std::span<const double> t_s, std::span<const double> v, std::size_t from);

}  // namespace rig::kpi
