#include "model/vehicle/tire_deflection.h"

#include <cmath>

namespace rig::model::vehicle {

TireDeflection::TireDeflection(VehicleBus& bus, const TireParams& tire, int wheel,
                               double velocity_floor_mps)
    : bus_(bus), tire_(tire), wheel_(wheel), velocity_floor_mps_(velocity_floor_mps) {}

void TireDeflection::rate(const Vector& s, Vector& f) const noexcept {
  const WheelBus& w = bus_.wheels[static_cast<std::size_t>(wheel_)];
  const double f_per_slip = w.f_per_slip;  // eq. (16) at the start of the step
  const double rolling = w.radius_dynamic_m * std::abs(w.spin_radps);
  // eq. (24) longitudinal and its lateral counterpart
  f(0) = deflection_rate(s(0), w.vx_mps - w.radius_dynamic_m * w.spin_radps, rolling,
                         w.curves.normalize_x, f_per_slip, tire_.longitudinal_stiffness_npm,
                         tire_.longitudinal_damping_nspm);
  f(1) = deflection_rate(s(1), w.vy_mps, rolling, w.curves.normalize_y, f_per_slip,
                         tire_.lateral_stiffness_npm, tire_.lateral_damping_nspm);
}

bool TireDeflection::rate_jacobian(const Vector& s, Matrix& df_ds) const noexcept {
  const WheelBus& w = bus_.wheels[static_cast<std::size_t>(wheel_)];
  const double f_per_slip = w.f_per_slip;  // eq. (16) at the start of the step
  const double rolling = w.radius_dynamic_m * std::abs(w.spin_radps);
  double dx = 0, dy = 0;
  (void)deflection_rate(s(0), 0, rolling, w.curves.normalize_x, f_per_slip,
                        tire_.longitudinal_stiffness_npm, tire_.longitudinal_damping_nspm, &dx);
  (void)deflection_rate(s(1), 0, rolling, w.curves.normalize_y, f_per_slip,
                        tire_.lateral_stiffness_npm, tire_.lateral_damping_nspm, &dy);
  df_ds << dx, 0, 0, dy;
  return true;
}

void limit_deflection(const TireParams& tire, const TmeasyLoadCurves& c, double& xe,
                      double& ye) noexcept {
  const double fxm = c.x.max_force_n, fym = c.y.max_force_n;
  if (fxm <= 0 || fym <= 0) {
    xe = 0;
    ye = 0;
    return;
  }
  const double ux = tire.longitudinal_stiffness_npm * xe / fxm;
  const double uy = tire.lateral_stiffness_npm * ye / fym;
  const double rho = std::sqrt(ux * ux + uy * uy);
  if (rho > 1.0) {
    xe /= rho;
    ye /= rho;
  }
}

void TireDeflection::after_update(Vector& s) noexcept {
  const WheelBus& w = bus_.wheels[static_cast<std::size_t>(wheel_)];
  limit_deflection(tire_, w.curves, s(0), s(1));
  bus_.deflection_m[static_cast<std::size_t>(2 * wheel_)] = s(0);
  bus_.deflection_m[static_cast<std::size_t>(2 * wheel_ + 1)] = s(1);
}

}  // namespace rig::model::vehicle
