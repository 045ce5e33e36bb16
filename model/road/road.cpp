#include "model/road/road.h"

#include <cmath>

namespace rig::model::road {

Road::Road(const RoadParams& params) noexcept : params_(params) {
  const double g = params.gravity_mps2;
  const double grade = std::atan(params.grade), bank = std::atan(params.bank);
  gravity_ = Eigen::Vector3d(-g * std::sin(grade), -g * std::cos(grade) * std::sin(bank),
                             -g * std::cos(grade) * std::cos(bank));
}

}  // namespace rig::model::road
