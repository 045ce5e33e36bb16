#pragma once
/// @file
/// An OpenDRIVE road as a Surface: a point (x, y) is projected onto the reference line
/// (model/road/opendrive_projection.h) to (s, t), t the horizontal lateral offset (> 0 left), and
///
///   z = elevation(s) + t tan(superelevation(s))
///
/// Superelevation is OpenDRIVE's roll of the cross section about the s-axis (right-handed,
/// s forward, t left, h up): a positive angle lifts the left side, i.e. the road falls to the
/// right (ASAM OpenDRIVE 1.7 sec. 8.3 and 10.5.2). OpenDRIVE measures t inside the tilted
/// section; the horizontal offset used here is t cos(phi), at height t sin(phi) = t_h tan(phi).
/// The gradient follows from grad s = T / (|C'| (1 - t kappa)) and grad t = n (T the tangent,
/// n the left normal):
///
///   grad z = (elevation' + t superelevation' / cos^2) grad s + tan(superelevation) n
///
/// Off the ends the reference line runs on straight along its end heading and the end's
/// elevation and superelevation are held (slope 0): model/road/DESIGN.md's rule. Lanes, lane
/// heights and the lateral `shape` profile are not applied (contact uses the reference line's
/// cross section, one plane per station).
///
/// Placement (model/road/placement.h): the road's point (s = u_m, t = v_m) goes to
/// (x_m, y_m, z_m) with the reference line's heading there turned to heading_rad; without one
/// the road sits where the file puts it (its x, y and elevation as the road frame's).

#include <Eigen/Core>

#include "model/road/opendrive_projection.h"
#include "model/road/opendrive_reference_line.h"
#include "model/road/opendrive_road.h"
#include "model/road/placement.h"
#include "model/road/road_profile.h"
#include "model/road/surface.h"

namespace rig::model::road {

class OpenDriveSurface final : public Surface {
 public:
  /// Throws std::invalid_argument for a plan view the reference line refuses (see there) or a
  /// placement with a non-finite number.
  ///
  /// The hint (model/road/surface.h): i is the reference line's element + 1 (-1: no idea), s_m
  /// the station, j the profile's segment.
  OpenDriveSurface(const OpenDriveRoad& road, const Placement& placement);

  [[nodiscard]] SurfaceHeight height(double x_m, double y_m,
                                     SurfaceHint& hint) const noexcept override;

  /// The station (s, t) of a road-frame point (with the placement applied).
  [[nodiscard]] Station station(double x_m, double y_m, SurfaceHint& hint) const noexcept;
  /// The road-frame (x, y) of the station (s, t): the inverse of station() within the reach.
  [[nodiscard]] Eigen::Vector2d position(double s_m, double t_m) const noexcept;

  [[nodiscard]] const OpenDriveReferenceLine& reference_line() const noexcept { return line_; }
  [[nodiscard]] const ReferenceLineProjection& projection() const noexcept { return projection_; }
  /// The elevation and superelevation at s (file heights, without the placement's shift).
  [[nodiscard]] CrossSection cross_section(double s_m) const noexcept {
    int segment = -1;
    return profile_.at(s_m, segment);
  }

 private:
  /// file coordinates from road-frame ones, and back (a rotation by heading_ and a shift)
  [[nodiscard]] Eigen::Vector2d to_file(double x_m, double y_m) const noexcept;
  [[nodiscard]] Eigen::Vector2d to_road(const Eigen::Vector2d& file_xy) const noexcept;

  OpenDriveReferenceLine line_;
  ReferenceLineProjection projection_;  // refers to line_ (declared after it)
  RoadProfile profile_;
  // road frame = rotation(turn_) * (file - file_origin_) + road_origin_; z shifted by z_shift_
  double cos_turn_ = 1, sin_turn_ = 0;
  Eigen::Vector2d file_origin_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d road_origin_ = Eigen::Vector2d::Zero();
  double z_shift_m_ = 0;
};

}  // namespace rig::model::road
