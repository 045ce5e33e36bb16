#pragma once
/// @file
/// Where a surface file's road goes in the world (the road frame the vehicle starts in): the
/// surface's reference point (u, v) - OpenCRG's reference line coordinates, OpenDRIVE's (s, t) of
/// the chosen road - is put at (x, y, z) with its reference line heading there. As OpenCRG's
/// reference-point modifier (RP_U, RP_V, RP_X, RP_Y, RP_Z, RP_PHI) does; without a placement a
/// surface sits where its file puts it.

#include <cmath>
#include <limits>

namespace rig::model::road {

struct Placement {
  bool given = false;  ///< false: where the file puts it (every other field ignored)
  /// The reference point on the surface [m]; NaN: the reference line's start (u_min / s = 0), v =
  /// 0.
  double u_m = std::numeric_limits<double>::quiet_NaN();
  double v_m = 0;
  double x_m = 0;  ///< where it goes, road frame [m]
  double y_m = 0;
  double z_m = 0;          ///< the surface's height there [m]
  double heading_rad = 0;  ///< the reference line's heading there (from +x, counter-clockwise)
};

}  // namespace rig::model::road
