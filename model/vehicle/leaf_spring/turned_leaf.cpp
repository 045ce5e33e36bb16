#include "model/vehicle/leaf_spring/turned_leaf.h"

#include <cmath>

namespace rig::model::vehicle::leaf_spring {

TurnedLeafForces evaluate_turned(const LeafSpring& leaf, const SeatPose& seat_pose,
                                 double alpha_rad, MovingEnd moving, LeafState& state) noexcept {
  const bool pin = moving == MovingEnd::kPin;
  const Eigen::Vector2d& fixed_m = pin ? leaf.geometry().eye_frame_m : leaf.geometry().pin_frame_m;
  const double c = std::cos(alpha_rad), s = std::sin(alpha_rad);
  Eigen::Matrix2d back;  // R(-alpha)
  back << c, s, -s, c;
  Eigen::Matrix2d turn;  // J: d R(phi) / d phi = R(phi) J
  turn << 0, -1, 1, 0;
  const Eigen::Vector2d arm = seat_pose.head<2>() - fixed_m;  // c - F
  SeatPose seen;
  seen << fixed_m + back * arm, seat_pose(2) + alpha_rad;
  TurnedLeafForces out;
  out.leaf = leaf.evaluate(seen, state);
  // G = d seat' / d(x, z, pitch, alpha)
  Eigen::Matrix<double, 3, 4> g = Eigen::Matrix<double, 3, 4>::Zero();
  g.topLeftCorner<2, 2>() = back;
  g.block<2, 1>(0, 3) = -back * turn * arm;
  g(2, 2) = 1;
  g(2, 3) = 1;
  const Eigen::Vector3d& q = out.leaf.on_axle;
  out.q.noalias() = g.transpose() * q;
  out.stiffness.noalias() = g.transpose() * out.leaf.d_on_axle_d_seat * g;
  // the turn's geometry: d2 seat'/dalpha2 = -R(-alpha)(c - F), d2 seat'/dc dalpha = -R(-alpha) J
  const Eigen::RowVector2d qb = q.head<2>().transpose() * back;
  out.stiffness(3, 3) -= qb.dot(arm);
  const Eigen::RowVector2d mixed = -qb * turn;
  out.stiffness.block<1, 2>(3, 0) += mixed;
  out.stiffness.block<2, 1>(0, 3) += mixed.transpose();
  // the moving end's force, turned back to frame axes: R(alpha) f', d/dalpha adds R(alpha) J f'
  const Eigen::Vector2d& f = pin ? out.leaf.on_frame_at_pin_n : out.leaf.on_frame_at_eye_n;
  const Eigen::Matrix<double, 2, 3>& df =
      pin ? out.leaf.d_on_frame_at_pin_d_seat : out.leaf.d_on_frame_at_eye_d_seat;
  const Eigen::Matrix2d ahead = back.transpose();  // R(alpha)
  out.end_force_n.noalias() = ahead * f;
  out.d_end_force.noalias() = ahead * df * g;
  out.d_end_force.col(3) += ahead * turn * f;
  return out;
}

}  // namespace rig::model::vehicle::leaf_spring
