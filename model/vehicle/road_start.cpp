#include "model/vehicle/road_start.h"

#include <cmath>

#include <Eigen/Cholesky>

namespace rig::model::vehicle {

GroundPlane ground_under(const VehicleFramework& f, double x_m, double y_m,
                         double yaw_rad) noexcept {
  const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  const auto add = [&](double bx, double by, bool right) {  // a body point (x fwd, y left)
    const double dx = c * bx - s * by, dy = s * bx + c * by;
    road::SurfaceHint hint;
    const double z = f.road().sample(x_m + dx, y_m + dy, right, hint).z_m;
    const Eigen::Vector3d row(1, dx, dy);
    a += row * row.transpose();
    b += row * z;
  };
  for (int i = 0; i < f.wheel_count(); ++i) add(f.mount(i).x(), f.mount(i).y(), i % 2 == 1);
  if (f.wheel_count() == 2) {  // one axle: a point fore and aft for the pitch
    add(1.0, 0.0, false);
    add(-1.0, 0.0, false);
  }
  const Eigen::Vector3d p = a.ldlt().solve(b);
  return {p(0), p(1), p(2)};
}

void place_on_road(VehicleState& s, const VehicleParams& p, const VehicleFramework& f) noexcept {
  if (!f.road().params().surface) return;
  auto& y = s.framework_y;
  const double yaw = y(3);
  const GroundPlane g = ground_under(f, y(0), y(1), yaw);
  // the slopes along and across the heading
  const double c = std::cos(yaw), sn = std::sin(yaw);
  const double along = c * g.dz_dx + sn * g.dz_dy, across = -sn * g.dz_dx + c * g.dz_dy;
  const double norm = std::sqrt(1 + along * along + across * across);
  // body z along the normal (-along, -across, 1)/norm in the yaw frame: Ry(pitch) Rx(roll) e_z
  // = (sin(pitch) cos(roll), -sin(roll), cos(pitch) cos(roll))
  y(4) = std::atan(-along);
  y(5) = std::asin(across / norm);
  // the CG cg_height from the plane, measured along its normal, straight above (x, y)
  y(2) = g.z0_m + p.chassis.cg_height_m * norm;
}

}  // namespace rig::model::vehicle
