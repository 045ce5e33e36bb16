#include "model/road/road_plane.h"

#include <cmath>

namespace rig::model::road {

double grade_percent_to_rad(double grade_percent) noexcept {
  return std::atan(grade_percent / 100.0);
}

RoadPlane::RoadPlane(const RoadPlaneParams& params) noexcept
    : params_(params), slope_x_(std::tan(params.grade_rad)), slope_y_(std::tan(params.bank_rad)) {
  normal_ = Eigen::Vector3d(-slope_x_, -slope_y_, 1.0).normalized();
}

}  // namespace rig::model::road
