#include "model/combination/joint.h"

namespace rig::model::combination {

using vehicle::body_rates_from_euler_rates;
using vehicle::body_to_road;
using vehicle::skew;

void Joint::evaluate(const Eigen::Ref<const Eigen::VectorXd>& y_a,
                     const Eigen::Ref<const Eigen::VectorXd>& y_b,
                     JointEvaluation& out) const noexcept {
  const Mat3 ra = body_to_road(y_a(3), y_a(4), y_a(5));
  const Mat3 rb = body_to_road(y_b(3), y_b(4), y_b(5));
  // omega_body = E(pitch, roll) [yaw', pitch', roll']
  const Mat3 ea = body_rates_from_euler_rates(y_a(4), y_a(5));
  const Mat3 eb = body_rates_from_euler_rates(y_b(4), y_b(5));
  // eq. (39), ball rows: g = r_a + R_a p_a - r_b - R_b p_b
  out.g.head<3>() =
      y_a.head<3>() + ra * p_.leading_point_m - y_b.head<3>() - rb * p_.trailing_point_m;
  // d(R p)/dt = R (omega x p) = -R [p]x E angles'  =>  d(R p)/d angles = -R [p]x E
  out.dg_dya.topLeftCorner<3, 3>().setIdentity();
  out.dg_dya.block<3, 3>(0, 3).noalias() = -(ra * skew(p_.leading_point_m)) * ea;
  out.dg_dyb.topLeftCorner<3, 3>() = -Mat3::Identity();
  out.dg_dyb.block<3, 3>(0, 3).noalias() = (rb * skew(p_.trailing_point_m)) * eb;
  if (p_.kind == JointKind::kFifthWheel) {
    // Cardan (fifth wheel) row: the tractor's pitch axis stays perpendicular to the kingpin
    const Vec3 pitch_axis = ra.col(1);  // R_a e_y
    const Vec3 kingpin = rb.col(2);     // R_b e_z
    out.g(3) = pitch_axis.dot(kingpin);
    // g' = omega_a . (e_y x R_a^T z_b) + omega_b . (e_z x R_b^T y_a)
    const Vec3 wa = Vec3::UnitY().cross(ra.transpose() * kingpin);
    const Vec3 wb = Vec3::UnitZ().cross(rb.transpose() * pitch_axis);
    out.dg_dya.block<1, 3>(3, 0).setZero();
    out.dg_dyb.block<1, 3>(3, 0).setZero();
    out.dg_dya.block<1, 3>(3, 3).noalias() = wa.transpose() * ea;
    out.dg_dyb.block<1, 3>(3, 3).noalias() = wb.transpose() * eb;
  }
}

}  // namespace rig::model::combination
