#pragma once
/// @file
/// Rigid-body kinematics of the chassis (method.md sec. 6): coordinates y_B = [x, y, z, yaw,
/// pitch, roll] in the road frame, speeds z_B = [v, omega] in body axes. K_BB is a rotation for
/// the position part and the Euler-rate matrix for the angles; both are inverted analytically.

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rig::model::vehicle {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Body-to-road rotation R = Rz(yaw) Ry(pitch) Rx(roll).
inline Mat3 body_to_road(double yaw, double pitch, double roll) noexcept {
  const double cy = std::cos(yaw), sy = std::sin(yaw);
  const double cp = std::cos(pitch), sp = std::sin(pitch);
  const double cr = std::cos(roll), sr = std::sin(roll);
  Mat3 r;
  r << cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,  //
      sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,   //
      -sp, cp * sr, cp * cr;
  return r;
}

/// Euler-angle rates [yaw', pitch', roll'] = E^-1(pitch, roll) omega_body (the angle part of
/// K_BB^-1). Singular only at pitch = +-90 deg.
inline Mat3 euler_rates_from_body_rates(double pitch, double roll) noexcept {
  const double cp = std::cos(pitch), tp = std::tan(pitch);
  const double cr = std::cos(roll), sr = std::sin(roll);
  Mat3 e;
  e << 0, sr / cp, cr / cp,  //
      0, cr, -sr,            //
      1, sr * tp, cr * tp;
  return e;
}

/// omega_body = E(pitch, roll) [yaw', pitch', roll'] (the angle part of K_BB).
inline Mat3 body_rates_from_euler_rates(double pitch, double roll) noexcept {
  const double cp = std::cos(pitch), sp = std::sin(pitch);
  const double cr = std::cos(roll), sr = std::sin(roll);
  Mat3 e;
  e << -sp, 0, 1,      //
      cp * sr, cr, 0,  //
      cp * cr, -sr, 0;
  return e;
}

/// Skew matrix: skew(a) b = a x b.
inline Mat3 skew(const Vec3& a) noexcept {
  Mat3 s;
  s << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return s;
}

}  // namespace rig::model::vehicle
