#pragma once
/// @file
/// Obstacles laid on a road: heights added to a base surface (model/road/layered_surface.h).
/// Each lies along a line through (x_m, y_m) with heading heading_rad; a point's coordinates on
/// it are a (along, from the line's origin) and b (across, > 0 to the left). The obstacle covers
/// s_m <= a <= s_m + length_m and |b| <= width_m / 2 (width_m infinite: across the whole road),
/// with vertical side walls at |b| = width_m / 2. With r = a - s_m and h = height_m:
///
///   cleat    a rectangular block (h > 0): z = h on the closed interval 0 <= r <= L, vertical
///            walls at both ends
///   pothole  a rectangular hole (h < 0, the depth): z = h on 0 <= r <= L, vertical walls
///   ramp     a trapezoid: up over rise_m (z = h r / rise), flat, down over fall_m; rise_m = 0 or
///            fall_m = 0 is a vertical wall (rise_m = L, fall_m = 0: a wedge)
///   bump     one haversine (cosine) hump: z = h/2 (1 - cos(2 pi r / L)), slopes 0 at both ends
///   sine     whole waves of wavelength_m: z = h/2 (1 - cos(2 pi r / wavelength)), L a whole
///            number of wavelengths (h the peak-to-peak height; no step at either end)
///
/// Walls have no gradient: a vertical face is where the height jumps, so the gradient there is
/// that of the flat on either side (0), and a point exactly on a wall is on top (the closed
/// interval). The contact (four probes around each wheel) sees the jump between its probes.
/// Constant after construction; height() noexcept and allocation-free.

#include <vector>

#include "model/road/surface.h"

namespace rig::model::road {

enum class ObstacleKind { kCleat, kPothole, kRamp, kBump, kSine };

struct ObstacleParams {
  ObstacleKind kind = ObstacleKind::kCleat;
  double x_m = 0;  ///< the line's origin, road frame
  double y_m = 0;
  double heading_rad = 0;   ///< the line's direction (from +x, counter-clockwise)
  double s_m = 0;           ///< where the obstacle starts along the line
  double length_m = 0;      ///< > 0
  double width_m = 0;       ///< > 0; infinity: across the whole road
  double height_m = 0;      ///< != 0 (pothole: < 0)
  double rise_m = 0;        ///< ramp: length of the up-slope (0 <= rise + fall <= length)
  double fall_m = 0;        ///< ramp: length of the down-slope
  double wavelength_m = 0;  ///< sine
};

/// One obstacle: its height (0 away from it) and gradient at (x, y).
class Obstacle {
 public:
  /// Throws std::invalid_argument on parameters outside the ranges above (io/config checks
  /// them first, with file:line).
  explicit Obstacle(const ObstacleParams& params);

  [[nodiscard]] SurfaceHeight height(double x_m, double y_m) const noexcept;
  [[nodiscard]] const ObstacleParams& params() const noexcept { return p_; }

 private:
  /// height and dz/da at r = a - s_m inside the obstacle's length
  [[nodiscard]] SurfaceHeight profile(double r_m) const noexcept;

  ObstacleParams p_;
  double cos_ = 1, sin_ = 0;
};

/// A set of obstacles as one surface (their heights and gradients summed; 0 away from all):
/// the overlay LayeredSurface adds to a base.
class Obstacles final : public Surface {
 public:
  explicit Obstacles(std::vector<Obstacle> obstacles) : obstacles_(std::move(obstacles)) {}

  [[nodiscard]] SurfaceHeight height(double x_m, double y_m,
                                     SurfaceHint& hint) const noexcept override;
  [[nodiscard]] const std::vector<Obstacle>& obstacles() const noexcept { return obstacles_; }

 private:
  std::vector<Obstacle> obstacles_;
};

}  // namespace rig::model::road
