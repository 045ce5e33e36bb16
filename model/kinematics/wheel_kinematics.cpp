#include "model/kinematics/wheel_kinematics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace rig::model::kinematics {
namespace {

bool same_grid(const Grid2D& a, const Grid2D& b) {
  return a.z_min == b.z_min && a.z_step == b.z_step && a.z_count == b.z_count &&
         a.u_min == b.u_min && a.u_step == b.u_step && a.u_count == b.u_count;
}

}  // namespace

WheelKinematics::WheelKinematics(KinematicTable x, KinematicTable y, KinematicTable alpha,
                                 KinematicTable beta, KinematicTable gamma, Interpolation method)
    : x_(std::move(x)),
      y_(std::move(y)),
      alpha_(std::move(alpha)),
      beta_(std::move(beta)),
      gamma_(std::move(gamma)),
      method_(method) {
  const Grid2D& g = x_.grid();
  if (!same_grid(g, y_.grid()) || !same_grid(g, alpha_.grid()) || !same_grid(g, beta_.grid()) ||
      !same_grid(g, gamma_.grid()))
    throw std::invalid_argument("wheel kinematics: the five tables must share one grid");
}

WheelPose WheelKinematics::evaluate(double hub_travel_m, double rack_travel_m) const noexcept {
  // one set of weights for all five functions of eq. (29)
  const TableWeights w = table_weights(x_.grid(), method_, hub_travel_m, rack_travel_m);
  return {x_.evaluate(w), y_.evaluate(w), alpha_.evaluate(w), beta_.evaluate(w),
          gamma_.evaluate(w)};
}

WheelPose evaluate_geometry(const SuspensionGeometry& g, double z, double u) noexcept {
  WheelPose p;
  p.x_m = {g.x0_m + g.x_per_z * z, g.x_per_z, 0.0};
  p.y_m = {g.y0_m + g.track_per_z * z + g.track_per_z2 * z * z + g.steer_y_per_u * u,
           g.track_per_z + 2.0 * g.track_per_z2 * z, g.steer_y_per_u};
  p.alpha_rad = {g.camber0_rad + g.camber_per_z * z, g.camber_per_z, 0.0};
  p.beta_rad = {g.beta_per_z * z, g.beta_per_z, 0.0};
  double steer = 0.0, d_steer = 0.0;
  if (g.steering_arm_m > 0.0) {
    // rack travel u moves the tie-rod end on a steering arm: sin(steer) = u / arm
    const double ratio = std::clamp(u / g.steering_arm_m, -0.99, 0.99);
    steer = std::asin(ratio);
    d_steer = std::abs(u / g.steering_arm_m) < 0.99
                  ? 1.0 / (g.steering_arm_m * std::sqrt(1.0 - ratio * ratio))
                  : 0.0;
    if (g.ackermann_cot_shift != 0.0) {
      // Ackermann: cot(gamma) = cot(gamma_arm) - k, as atan2 without the pole at gamma = 0;
      // dgamma/dgamma_arm = 1 / ((cos - k sin)^2 + sin^2)
      const double sn = std::sin(steer), cs = std::cos(steer) - g.ackermann_cot_shift * sn;
      steer = std::atan2(sn, cs);
      d_steer /= cs * cs + sn * sn;
    }
  }
  p.gamma_rad = {g.toe0_rad + g.bump_steer_per_z * z + steer, g.bump_steer_per_z, d_steer};
  return p;
}

WheelKinematics generate_wheel_kinematics(const SuspensionGeometry& geometry, const Grid2D& grid,
                                          Interpolation method) {
  const std::size_t n =
      static_cast<std::size_t>(grid.z_count) * static_cast<std::size_t>(grid.u_count);
  std::vector<double> x(n), y(n), a(n), b(n), c(n);
  for (int k = 0; k < grid.z_count; ++k) {
    for (int l = 0; l < grid.u_count; ++l) {
      const WheelPose p =
          evaluate_geometry(geometry, grid.z_min + k * grid.z_step, grid.u_min + l * grid.u_step);
      const std::size_t i = static_cast<std::size_t>(k * grid.u_count + l);
      x[i] = p.x_m.value;
      y[i] = p.y_m.value;
      a[i] = p.alpha_rad.value;
      b[i] = p.beta_rad.value;
      c[i] = p.gamma_rad.value;
    }
  }
  return WheelKinematics(KinematicTable(grid, std::move(x)), KinematicTable(grid, std::move(y)),
                         KinematicTable(grid, std::move(a)), KinematicTable(grid, std::move(b)),
                         KinematicTable(grid, std::move(c)), method);
}

}  // namespace rig::model::kinematics
