#pragma once
/// @file
/// The local road plane under one wheel (TMeasy's contact calculation, G. Rill, Road Vehicle
/// Dynamics, 2011, sec. 3.2: "local track plane"): the road is probed at four points around the
/// static contact point - fore and aft along the tire's heading, left and right across it - and
/// replaced by the plane through their mean with the normal (Q_fore - Q_aft) x (Q_left -
/// Q_right). A 2 cm cleat then lifts and tilts the plane for as long as one probe is on it, a
/// vertical force history instead of a spike; on a plane (tilted or not) the result is that plane
/// exactly. Probe distances: dx = 0.1 r_0 fore and aft, dy = 0.3 B left and right (r_0 the
/// unloaded radius, B the contact width), as Rill suggests there. Four road queries per call,
/// each from its own SurfaceHint; allocation-free.

#include <array>
#include <cmath>

#include "model/road/road.h"
#include "model/vehicle/chassis_kinematics.h"

namespace rig::model::vehicle {

/// Where the probes sit relative to the static contact point [m].
struct ContactProbes {
  double fore_aft_m = 0.035;  ///< dx: 0.1 r_0
  double lateral_m = 0.06;    ///< dy: 0.3 B
};

/// The plane a wheel's contact is evaluated on over one step (road frame).
struct LocalRoadPlane {
  Vec3 point_m = Vec3::Zero();  ///< the probes' mean: a point of the plane
  Vec3 normal = Vec3::UnitZ();  ///< upward unit normal
  double mu = 1.0;              ///< the road's friction scale: the probes' mean
};

/// The probes' hints, in the order fore, aft, left, right (model/road/surface.h).
using ProbeHints = std::array<road::SurfaceHint, 4>;

/// The local plane around `foot_m` (the static contact point, road frame; only x and y are
/// used), with the tire heading `heading` (road frame; its horizontal direction is used).
/// `right_side` picks the plane road's split mu (road::Road::sample).
[[nodiscard]] inline LocalRoadPlane local_road_plane(const road::Road& road, const Vec3& foot_m,
                                                     const Vec3& heading,
                                                     const ContactProbes& probes, bool right_side,
                                                     ProbeHints& hints) noexcept {
  double hx = heading.x(), hy = heading.y();
  const double h = std::hypot(hx, hy);
  if (h > 0) {
    hx /= h;
    hy /= h;
  } else {  // a heading straight up or down (never a rolling wheel): any horizontal direction
    hx = 1;
    hy = 0;
  }
  const double dx = probes.fore_aft_m, dy = probes.lateral_m;
  const double px[4] = {foot_m.x() + dx * hx, foot_m.x() - dx * hx, foot_m.x() - dy * hy,
                        foot_m.x() + dy * hy};
  const double py[4] = {foot_m.y() + dx * hy, foot_m.y() - dx * hy, foot_m.y() + dy * hx,
                        foot_m.y() - dy * hx};
  std::array<road::RoadSample, 4> q;
  for (std::size_t k = 0; k < 4; ++k) q[k] = road.sample(px[k], py[k], right_side, hints[k]);
  LocalRoadPlane plane;
  const Vec3 along(px[0] - px[1], py[0] - py[1], q[0].z_m - q[1].z_m);
  const Vec3 across(px[2] - px[3], py[2] - py[3], q[2].z_m - q[3].z_m);
  plane.normal = along.cross(across).normalized();  // z = 4 dx dy > 0: upward
  plane.point_m =
      Vec3(0.25 * (px[0] + px[1] + px[2] + px[3]), 0.25 * (py[0] + py[1] + py[2] + py[3]),
           0.25 * (q[0].z_m + q[1].z_m + q[2].z_m + q[3].z_m));
  plane.mu = 0.25 * (q[0].mu + q[1].mu + q[2].mu + q[3].mu);
  return plane;
}

}  // namespace rig::model::vehicle
