#include "model/road/opendrive_surface.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rig::model::road {

OpenDriveSurface::OpenDriveSurface(const OpenDriveRoad& road, const Placement& placement)
    : line_(road.plan_view),
      projection_(line_),
      profile_(road.elevation, road.superelevation, line_.start_s_m(), line_.end_s_m()) {
  if (!placement.given) return;
  const double u = std::isnan(placement.u_m) ? line_.start_s_m() : placement.u_m;
  for (const double v :
       {u, placement.v_m, placement.x_m, placement.y_m, placement.z_m, placement.heading_rad}) {
    if (!std::isfinite(v)) throw std::invalid_argument("placement: a number is not finite");
  }
  int element = -1;
  const ReferencePose p = line_.pose(u, element);
  const double turn = placement.heading_rad - p.hdg_rad;
  cos_turn_ = std::cos(turn);
  sin_turn_ = std::sin(turn);
  file_origin_ = {p.x_m - placement.v_m * p.sin_hdg, p.y_m + placement.v_m * p.cos_hdg};
  road_origin_ = {placement.x_m, placement.y_m};
  const CrossSection section = cross_section(u);
  const double z_file = section.elevation_m + placement.v_m * section.tan_superelevation;
  z_shift_m_ = placement.z_m - z_file;
}

Eigen::Vector2d OpenDriveSurface::to_file(double x_m, double y_m) const noexcept {
  const double dx = x_m - road_origin_.x(), dy = y_m - road_origin_.y();
  return {file_origin_.x() + cos_turn_ * dx + sin_turn_ * dy,
          file_origin_.y() - sin_turn_ * dx + cos_turn_ * dy};
}

Eigen::Vector2d OpenDriveSurface::to_road(const Eigen::Vector2d& file_xy) const noexcept {
  const Eigen::Vector2d d = file_xy - file_origin_;
  return {road_origin_.x() + cos_turn_ * d.x() - sin_turn_ * d.y(),
          road_origin_.y() + sin_turn_ * d.x() + cos_turn_ * d.y()};
}

Station OpenDriveSurface::station(double x_m, double y_m, SurfaceHint& hint) const noexcept {
  const Eigen::Vector2d f = to_file(x_m, y_m);
  return projection_.project(f.x(), f.y(), hint);
}

Eigen::Vector2d OpenDriveSurface::position(double s_m, double t_m) const noexcept {
  int element = -1;
  const ReferencePose p = line_.pose(s_m, element);
  return to_road({p.x_m - t_m * p.sin_hdg, p.y_m + t_m * p.cos_hdg});
}

SurfaceHeight OpenDriveSurface::height(double x_m, double y_m, SurfaceHint& hint) const noexcept {
  const Station st = station(x_m, y_m, hint);
  if (!st.found) {
    const double nan = std::nan("");
    return {nan, nan, nan};
  }
  const CrossSection cs = profile_.at(st.s_m, hint.j);
  const double tan_phi = cs.tan_superelevation;
  const double cos_phi = cs.cos_superelevation;
  const ReferencePose& p = st.pose;
  // dz/ds at fixed t, dz/dt at fixed s; grad s = T / (|C'| (1 - t kappa)), grad t = n
  const double dz_ds = cs.elevation_slope + st.t_m * cs.superelevation_rate / (cos_phi * cos_phi);
  // (1 - t kappa) > 0.1 wherever Newton found the foot; the clamp guards the golden-section
  // fallback's feet near a centre of curvature
  const double ds_scale = dz_ds / (p.speed * std::max(1.0 - st.t_m * p.curvature_1pm, 0.1));
  const double c = p.cos_hdg, s = p.sin_hdg;
  const double gx = ds_scale * c - tan_phi * s;  // file frame
  const double gy = ds_scale * s + tan_phi * c;
  return {cs.elevation_m + st.t_m * tan_phi + z_shift_m_, cos_turn_ * gx - sin_turn_ * gy,
          sin_turn_ * gx + cos_turn_ * gy};
}

}  // namespace rig::model::road
