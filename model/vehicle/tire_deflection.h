#pragma once
/// @file
/// The first-order TMeasy tire dynamics of one wheel as a force element (eq. 3): states the
/// deflections x_e, y_e; rates by eq. (24); limiter by eq. (26) (elliptic in x, y).

#include <Eigen/Core>

#include "model/solver/force_element.h"
#include "model/vehicle/vehicle_bus.h"

namespace rig::model::vehicle {

/// Deflection rate of eq. (24) for one direction; also returns d(rate)/d(deflection).
/// @param slip_speed v_x - r_D omega (or v_y laterally)
inline double deflection_rate(double deflection_m, double slip_speed_mps, double rolling_mps,
                              double normalize, double f_per_slip, double stiffness, double damping,
                              double* d_rate_d_deflection = nullptr) noexcept {
  const double rs = rolling_mps * normalize;
  const double denom = damping * rs + f_per_slip + 1e-9;
  if (d_rate_d_deflection) *d_rate_d_deflection = -stiffness * rs / denom;
  return (-f_per_slip * slip_speed_mps - stiffness * deflection_m * rs) / denom;
}

class TireDeflection final : public solver::ForceElement<2> {
 public:
  TireDeflection(VehicleBus& bus, const TireParams& tire, int wheel, double velocity_floor_mps);
  [[nodiscard]] Eigen::Index state_size() const noexcept override { return 2; }
  [[nodiscard]] Vector& state() noexcept override { return s_; }
  void rate(const Vector& s, Vector& f) const noexcept override;
  bool rate_jacobian(const Vector& s, Matrix& df_ds) const noexcept override;
  void after_update(Vector& s) noexcept override;

 private:
  VehicleBus& bus_;
  const TireParams& tire_;
  int wheel_;
  double velocity_floor_mps_;
  Vector s_ = Vector::Zero();
};

/// Eq. (26), elliptic: scales (x_e, y_e) so that (c_x x_e / F_xM)^2 + (c_y y_e / F_yM)^2 <= 1.
void limit_deflection(const TireParams& tire, const TmeasyLoadCurves& c, double& xe,
                      double& ye) noexcept;

}  // namespace rig::model::vehicle
