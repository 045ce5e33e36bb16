#pragma once
/// @file
/// Friction zones: a FrictionField (model/road/friction_field.h) made of areas of the road frame,
/// each with its own mu (the tires' friction scale, replacing the road's there). Where zones
/// overlap the later one wins; outside all of them the road's own mu holds.
///
///   rectangle  along a line through (x_m, y_m) with heading heading_rad: a point's a (along)
///              in [s_from_m, s_to_m] and b (across, > 0 left) in [v_from_m, v_to_m], closed;
///              the bounds may be infinite: a mu-split is a half-plane (v_to_m = 0: right of
///              the line), a mu-jump a half-plane along it (s_from_m = 50, s_to_m = inf), a patch
///              a finite rectangle
///   polygon    a simple polygon in x/y (at least 3 corners, either orientation, not closed
///              explicitly): inside by the even-odd rule, and its edges count as inside
///
/// Constant after construction; mu() noexcept and allocation-free (a zone's bounding box is
/// checked before its shape).

#include <vector>

#include "model/road/friction_field.h"

namespace rig::model::road {

struct FrictionRectangle {
  double x_m = 0, y_m = 0, heading_rad = 0;
  double s_from_m = 0, s_to_m = 0;  ///< along the line, s_from_m < s_to_m (may be infinite)
  double v_from_m = 0, v_to_m = 0;  ///< across, v_from_m < v_to_m (may be infinite)
};

struct FrictionPolygon {
  std::vector<double> x_m, y_m;  ///< the corners, as many of each, at least 3
};

struct FrictionZone {
  double mu = 1;
  bool is_polygon = false;
  FrictionRectangle rectangle;
  FrictionPolygon polygon;
};

class FrictionZones final : public FrictionField {
 public:
  /// Throws std::invalid_argument for a mu that is negative or not finite, empty ranges, NaN,
  /// polygons with fewer than 3 corners or non-finite ones (io/config checks first, file:line).
  explicit FrictionZones(std::vector<FrictionZone> zones);

  [[nodiscard]] double mu(double x_m, double y_m, double base_mu) const noexcept override;
  [[nodiscard]] std::size_t size() const noexcept { return zones_.size(); }

 private:
  struct Prepared {
    FrictionZone zone;
    double cos = 1, sin = 0;
    double min_x = 0, max_x = 0, min_y = 0, max_y = 0;  ///< polygon bounding box
  };
  [[nodiscard]] static bool inside(const Prepared& z, double x_m, double y_m) noexcept;
  [[nodiscard]] static bool inside_polygon(const Prepared& z, double x_m, double y_m) noexcept;

  std::vector<Prepared> zones_;
};

}  // namespace rig::model::road
