#include "model/vehicle/vehicle_faults.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "model/vehicle/chassis_kinematics.h"
#include "model/vehicle/free_body/free_bodies.h"

namespace rig::model::vehicle {
namespace {

ModelFault fault(FaultKind kind, int index, double time_s, double value, double limit) noexcept {
  ModelFault f;
  f.kind = kind;
  f.index = index;
  f.time_s = time_s;
  f.value = value;
  f.limit = limit;
  return f;
}

void check_limits(const FaultLimits& l) {
  for (const double v : {l.roll_rad, l.pitch_rad, l.speed_mps, l.rate_radps}) {
    if (!(v > 0) || !std::isfinite(v))
      throw std::invalid_argument("vehicle: fault limits must be finite and > 0");
  }
}

}  // namespace

std::vector<std::array<double, 3>> default_body_points(const VehicleParams& p) {
  double front = -1e9, rear = 1e9, half_track = 0, floor = 1e9;
  for (const AxleParams& a : p.axles) {
    front = std::max(front, a.position_x_m);
    rear = std::min(rear, a.position_x_m);
    half_track = std::max(half_track, 0.5 * a.track_m);
    floor = std::min(floor, a.tire.tmeasy.radius_unloaded_m);
  }
  if (p.chassis.supported) {
    front = std::max(front, p.chassis.support_x_m);
    rear = std::min(rear, p.chassis.support_x_m);
  }
  const double h = p.chassis.cg_height_m;
  std::vector<std::array<double, 3>> points;
  for (const double x : {front, rear}) {
    for (const double y : {half_track, -half_track}) {
      for (const double z : {floor - h, h}) points.push_back({x, y, z});
    }
  }
  return points;
}

FaultCheck::FaultCheck(const VehicleParams& p)
    : limits_(p.fault_limits),
      free_bodies_(p.free_bodies),
      road_(p.road),
      wheel_count_(2 * static_cast<int>(p.axles.size())) {
  check_limits(limits_);
  const std::vector<std::array<double, 3>> points =
      p.chassis.body_points_m.empty() ? default_body_points(p) : p.chassis.body_points_m;
  if (points.size() > static_cast<std::size_t>(kMaxBodyPoints))
    throw std::invalid_argument("vehicle: at most " + std::to_string(kMaxBodyPoints) +
                                " body points");
  point_count_ = static_cast<int>(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    points_[i] = Vec3(points[i][0], points[i][1], points[i][2]);
  for (std::size_t k = 0; k < static_cast<std::size_t>(wheel_count_) && k < kMaxWheels; ++k)
    spin_limit_radps_[k] = limits_.speed_mps / p.axles[k / 2].tire.tmeasy.radius_unloaded_m;
  for (const FreeBodyParams& b : free_bodies_) {
    std::array<Mount, kMaxMounts> mounts{};
    const Vec3 position(b.position_m[0], b.position_m[1], b.position_m[2]);
    for (std::size_t i = 0; i < b.mounts.size() && i < kMaxMounts; ++i)
      mounts[i] = make_mount(b.mounts[i], position, b.through_margin_m);
    free_body_mounts_.push_back(mounts);
  }
}

ModelFault FaultCheck::check(const VehicleState& s, double time_s) const noexcept {
  if (!is_finite(s)) {
    return fault(FaultKind::kNonFinite, -1, time_s, std::numeric_limits<double>::quiet_NaN(), 0);
  }
  const auto& y = s.framework_y;
  const auto& z = s.framework_z;
  const double speed = z.head<3>().norm();
  if (speed > limits_.speed_mps)
    return fault(FaultKind::kSpeed, -1, time_s, speed, limits_.speed_mps);
  const double rate = z.segment<3>(3).norm();
  if (rate > limits_.rate_radps)
    return fault(FaultKind::kRate, -1, time_s, rate, limits_.rate_radps);
  for (int i = 0; i < wheel_count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (std::abs(s.spin_radps[k]) > spin_limit_radps_[k])
      return fault(FaultKind::kWheelSpin, i, time_s, s.spin_radps[k], spin_limit_radps_[k]);
  }
  if (std::abs(y(5)) > limits_.roll_rad)
    return fault(FaultKind::kRoll, -1, time_s, y(5), limits_.roll_rad);
  if (std::abs(y(4)) > limits_.pitch_rad)
    return fault(FaultKind::kPitch, -1, time_s, y(4), limits_.pitch_rad);
  const ModelFault f = check_body_points(y, time_s);
  if (f.kind != FaultKind::kNone) return f;
  return check_free_bodies(s, time_s);
}

ModelFault FaultCheck::check_free_bodies(const VehicleState& s, double time_s) const noexcept {
  for (std::size_t i = 0; i < free_bodies_.size() && i < kMaxFreeBodies; ++i) {
    const FreeBodyParams& b = free_bodies_[i];
    const double beyond =
        free_body_beyond_stop_m(b, static_cast<int>(i), s, free_body_mounts_[i].data());
    if (beyond > b.through_margin_m)
      return fault(FaultKind::kFreeBodyStops, static_cast<int>(i), time_s, beyond,
                   b.through_margin_m);
  }
  return {};
}

ModelFault FaultCheck::check_body_points(const Eigen::VectorXd& y, double time_s) const noexcept {
  const Mat3 r = body_to_road(y(3), y(4), y(5));
  const Vec3 cg = y.head<3>();
  for (int i = 0; i < point_count_; ++i) {
    const Vec3 p = cg + r * points_[static_cast<std::size_t>(i)];  // road frame
    const auto k = static_cast<std::size_t>(i);
    const double ground = road_.is_plane() ? road_.height_m(p.x(), p.y())
                                           : road_.sample(p.x(), p.y(), false, hints_[k]).z_m;
    const double height = p.z() - ground;
    if (height < 0) return fault(FaultKind::kBodyGround, i, time_s, height, 0);
  }
  return {};
}

}  // namespace rig::model::vehicle
