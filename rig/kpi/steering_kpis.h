#pragma once
/// @file
/// The steering maneuvers' KPIs (parking effort, ISO 13674-1 weave, returnability) as small
/// functions over a recorded series (docs/kpis.md). NaN when the series has no answer (no
/// crossing, no sample in the window).

#include <span>

namespace rig::kpi {

/// max |y|.
double peak_abs(std::span<const double> y);

/// The loop's width at x = x0: the mean y where x rises through x0 minus the mean y where it
/// falls through x0 (linear interpolation between samples), as a magnitude. Parking: rack force
/// at the centre going left vs right; ISO 13674-1: torque deadband (y = torque, x = a_y, x0 = 0)
/// and a_y hysteresis (y = a_y, x = torque, x0 = 0).
double loop_width(std::span<const double> x, std::span<const double> y, double x0);

/// dy/dx at x0: least-squares slope of y over the samples with |x - x0| <= band (both branches
/// of a loop, so the loop's mean gradient). ISO 13674-1 torque gradient at 0 and 1 m/s^2.
double gradient(std::span<const double> x, std::span<const double> y, double x0, double band);

/// |y(t1)| / |y(t0)| (nearest samples). Returnability: the residual angle's fraction.
double residual_fraction(std::span<const double> t_s, std::span<const double> y, double t0_s,
                         double t1_s);

}  // namespace rig::kpi
