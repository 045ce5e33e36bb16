#include "model/road/road.h"

#include <cmath>

namespace rig::model::road {

Road::Road(const RoadParams& params) noexcept : params_(params) {
  const double g = params.gravity_mps2;
  // with a surface the ground itself slopes: gravity straight down
  const bool plane = !params.surface;
  const double grade = plane ? std::atan(params.grade) : 0.0;
  const double bank = plane ? std::atan(params.bank) : 0.0;
  gravity_ = Eigen::Vector3d(-g * std::sin(grade), -g * std::cos(grade) * std::sin(bank),
                             -g * std::cos(grade) * std::cos(bank));
}

RoadSample Road::sample(double x_m, double y_m, bool right_side, SurfaceHint& hint) const noexcept {
  RoadSample r;
  r.mu = friction(right_side);
  if (params_.surface) {
    const SurfaceHeight h = params_.surface->height(x_m, y_m, hint);
    r.z_m = h.z_m;
    r.normal = Eigen::Vector3d(-h.dz_dx, -h.dz_dy, 1.0).normalized();
  }
  if (params_.friction_field) r.mu = params_.friction_field->mu(x_m, y_m, r.mu);
  return r;
}

}  // namespace rig::model::road
