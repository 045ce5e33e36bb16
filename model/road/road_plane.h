#pragma once
/// @file
/// A flat road plane of configurable grade, bank and friction (issue 6, force elements). The
/// height is z(x, y) = x tan(grade) + y tan(bank) in the inertial frame (x forward/uphill for a
/// positive grade, y left, z up), so a vehicle heading +x climbs a positive grade and a positive
/// bank raises the left (+y) side. Allocation-free, noexcept, constexpr where possible.

#include <Eigen/Core>

namespace rig::model::road {

/// Road plane parameters.
struct RoadPlaneParams {
  double grade_rad = 0;   ///< inclination along x (atan of the grade ratio)
  double bank_rad = 0;    ///< inclination along y
  double friction = 1.0;  ///< mu, the same everywhere on this plane
};

/// Grade given in percent (10 % = rise 0.1 per 1 m run) to the inclination angle [rad].
[[nodiscard]] double grade_percent_to_rad(double grade_percent) noexcept;

/// The road plane: height, normal and friction at (x, y), with derivatives.
class RoadPlane {
 public:
  explicit RoadPlane(const RoadPlaneParams& params = {}) noexcept;

  [[nodiscard]] const RoadPlaneParams& params() const noexcept { return params_; }
  /// Road height z at (x, y) [m].
  [[nodiscard]] double height_m(double x_m, double y_m) const noexcept {
    return slope_x_ * x_m + slope_y_ * y_m;
  }
  /// (dz/dx, dz/dy) of the height; constant on a plane.
  [[nodiscard]] Eigen::Vector2d height_gradient(double x_m, double y_m) const noexcept {
    (void)x_m;
    (void)y_m;
    return {slope_x_, slope_y_};
  }
  /// Unit normal (pointing up, out of the road) at (x, y): (-dz/dx, -dz/dy, 1)/norm.
  [[nodiscard]] const Eigen::Vector3d& normal(double x_m, double y_m) const noexcept {
    (void)x_m;
    (void)y_m;
    return normal_;
  }
  /// Friction coefficient mu at (x, y).
  [[nodiscard]] double friction(double x_m, double y_m) const noexcept {
    (void)x_m;
    (void)y_m;
    return params_.friction;
  }
  /// Signed distance of point p above the plane, along the normal [m], and its gradient (= the
  /// normal): the tire's vertical deflection is r_0 - distance of the wheel centre (for an
  /// upright wheel).
  [[nodiscard]] double distance_m(const Eigen::Vector3d& p) const noexcept {
    return normal_.dot(p);  // the plane passes through the origin
  }
  /// The projection of a point onto the plane (contact point of a sphere-like wheel).
  [[nodiscard]] Eigen::Vector3d project(const Eigen::Vector3d& p) const noexcept {
    return p - distance_m(p) * normal_;
  }

 private:
  RoadPlaneParams params_;
  double slope_x_ = 0;  ///< tan(grade)
  double slope_y_ = 0;  ///< tan(bank)
  Eigen::Vector3d normal_ = Eigen::Vector3d::UnitZ();
};

}  // namespace rig::model::road
