#include "model/combination/combination_hold.h"

#include "model/vehicle/free_body/mount.h"

namespace rig::model::combination {
namespace {

/// Road-frame velocity of a body point (body axes, from the CG): R (v + omega x r).
Vec3 point_velocity_mps(const vehicle::RigidPose& body, const Vec3& point) noexcept {
  return body.rot * (body.velocity_mps + body.rate_radps.cross(point));
}

}  // namespace

double joint_following_lateral_speed_mps(const vehicle::VehicleState& a, const Vec3& point_a,
                                         const vehicle::VehicleState& b,
                                         const Vec3& point_b) noexcept {
  const vehicle::RigidPose pa = vehicle::rigid_pose(a.framework_y, a.framework_z);
  const vehicle::RigidPose pb = vehicle::rigid_pose(b.framework_y, b.framework_z);
  const double miss_mps = point_velocity_mps(pa, point_a).y() - point_velocity_mps(pb, point_b).y();
  // b's body-y speed moves its point along R e_y: road lateral R(1,1) per m/s
  return pb.velocity_mps.y() + miss_mps / pb.rot(1, 1);
}

void hold_in_line(std::vector<std::unique_ptr<vehicle::VehicleModel>>& units,
                  const std::vector<JointParams>& joints, double speed_mps) noexcept {
  units[0]->hold_plane_motion(speed_mps);
  for (std::size_t k = 0; k + 1 < units.size(); ++k) {
    vehicle::VehicleModel& b = *units[k + 1];
    b.hold_plane_motion(speed_mps);  // speed, no yaw rate: the lateral speed below sees them
    const double lateral_mps = joint_following_lateral_speed_mps(
        units[k]->state(), joints[k].leading_point_m, b.state(), joints[k].trailing_point_m);
    b.hold_plane_motion(speed_mps, lateral_mps);
  }
}

}  // namespace rig::model::combination
