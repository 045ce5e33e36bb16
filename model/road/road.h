#pragma once
/// @file
/// The road the tires touch: a surface (model/road/surface.h; none: the plane z = 0 of the road
/// frame, in which the vehicle's coordinates are given), a friction field, and gravity. On the
/// plane its grade and bank tilt gravity instead of the plane, so that a vehicle on a grade keeps
/// its design height, and mu may differ under the right-hand wheels (split mu). With a surface,
/// gravity is straight down and the surface carries every slope. Queries are per contact and
/// evaluation: noexcept, allocation-free.

#include <Eigen/Core>
#include <memory>

#include "model/road/friction_field.h"
#include "model/road/surface.h"

namespace rig::model::road {

struct RoadParams {
  double grade = 0;  ///< tan of the uphill slope in +x [-] (0.2 = 20 %)
  double bank = 0;   ///< tan of the bank slope, uphill in +y [-]
  /// Scales F_M and F_S of all tires by friction / their reference_friction: 1 = the tire data as
  /// given (whose own peak F_M / F_z may well exceed 1), not a peak friction of 1.
  double friction = 1.0;
  /// Split mu: mu under the right-hand wheels; < 0: the same as friction.
  double friction_right = -1.0;
  double gravity_mps2 = 9.81;
  /// The ground's height; nullptr: the plane z = 0 (grade and bank then tilt gravity).
  std::shared_ptr<const Surface> surface;
  /// mu over (x, y) on top of `friction`; nullptr: `friction` (and `friction_right`) everywhere.
  std::shared_ptr<const FrictionField> friction_field;
};

/// The road under one point: height, upward unit normal (road frame) and the tires' mu scale.
struct RoadSample {
  double z_m = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double mu = 1.0;
};

class Road {
 public:
  explicit Road(const RoadParams& params) noexcept;

  [[nodiscard]] const RoadParams& params() const noexcept { return params_; }
  /// Today's plane: no surface and no friction field (every query a constant; bit-identical).
  [[nodiscard]] bool is_plane() const noexcept {
    return !params_.surface && !params_.friction_field;
  }
  /// The road at (x, y) [m]; `hint` is the probe's own (model/road/surface.h). right_side picks
  /// the plane's split mu (a friction field's zones are where they are, whichever wheel).
  [[nodiscard]] RoadSample sample(double x_m, double y_m, bool right_side,
                                  SurfaceHint& hint) const noexcept;
  /// Gravity in the road frame [m/s^2]: the grade tilts it towards -x, the bank towards -y.
  [[nodiscard]] const Eigen::Vector3d& gravity_mps2() const noexcept { return gravity_; }
  /// Height of the surface above z = 0 of the road frame at (x, y) [m].
  [[nodiscard]] double height_m(double x_m, double y_m) const noexcept {
    (void)x_m;
    (void)y_m;
    return 0.0;
  }
  /// Unit normal of the surface at (x, y), road frame.
  [[nodiscard]] const Eigen::Vector3d& normal(double x_m, double y_m) const noexcept {
    (void)x_m;
    (void)y_m;
    return normal_;
  }
  /// mu under a left-hand (right_side = false) or right-hand wheel.
  [[nodiscard]] double friction(bool right_side) const noexcept {
    return right_side && params_.friction_right >= 0 ? params_.friction_right : params_.friction;
  }

 private:
  RoadParams params_;
  Eigen::Vector3d gravity_;
  Eigen::Vector3d normal_ = Eigen::Vector3d::UnitZ();
};

}  // namespace rig::model::road
