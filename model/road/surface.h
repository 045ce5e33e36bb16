#pragma once
/// @file
/// A road surface: the height of the ground the tires touch as a function of (x, y) of the road
/// (world) frame, and its slope there. Every kind of road (the plane, an OpenCRG grid, an
/// OpenDRIVE reference line with elevation and superelevation, an ISO 8608 random grid,
/// obstacles laid over a base) is one implementation; model/road/road.h combines them with the
/// friction field and gravity. Surfaces are constant after construction; a query is noexcept,
/// allocation-free and starts from the caller's hint (the grid cell or reference-line station
/// of the same probe's last query), so that a wheel rolling along costs a cell step, not a search.

namespace rig::model::road {

/// Where a probe's last query landed on a surface; kept by the caller (one per contact probe),
/// read and updated by the surface. Its meaning is the surface's own (cell indices, station s);
/// a default-constructed hint means "no idea", and any hint gives the same answer, only faster.
struct SurfaceHint {
  int i = -1;      ///< e.g. the grid column (u) or the geometry element
  int j = -1;      ///< e.g. the grid row (v)
  double s_m = 0;  ///< e.g. the last station along a reference line
};

/// Height and slope at one point. The upward unit normal is (-dz_dx, -dz_dy, 1) normalised.
struct SurfaceHeight {
  double z_m = 0;
  double dz_dx = 0;
  double dz_dy = 0;
};

class Surface {
 public:
  Surface() = default;
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;
  virtual ~Surface() = default;

  /// Height [m] and gradient of the surface at (x, y) [m] of the road frame. Off the surface's
  /// extent each implementation applies its stated border rule (never NaN).
  [[nodiscard]] virtual SurfaceHeight height(double x_m, double y_m,
                                             SurfaceHint& hint) const noexcept = 0;
};

}  // namespace rig::model::road
