#include "model/combination/joint.h"

#include <cmath>

namespace rig::model::combination {

using vehicle::skew;

namespace {

/// R = body_to_road(yaw, pitch, roll) and E = body_rates_from_euler_rates(pitch, roll) (omega_body
/// = E [yaw', pitch', roll']) from one sin/cos per angle (chassis_kinematics.h has them apart).
void attitude(const Eigen::Ref<const Eigen::VectorXd>& y, Mat3& r, Mat3& e) noexcept {
  const double cy = std::cos(y(3)), sy = std::sin(y(3));
  const double cp = std::cos(y(4)), sp = std::sin(y(4));
  const double cr = std::cos(y(5)), sr = std::sin(y(5));
  r << cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,  //
      sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,   //
      -sp, cp * sr, cp * cr;
  e << -sp, 0, 1,      //
      cp * sr, cr, 0,  //
      cp * cr, -sr, 0;
}

}  // namespace

void Joint::evaluate(const Eigen::Ref<const Eigen::VectorXd>& y_a,
                     const Eigen::Ref<const Eigen::VectorXd>& y_b,
                     JointEvaluation& out) const noexcept {
  Mat3 ra, rb, ea, eb;
  attitude(y_a, ra, ea);
  attitude(y_b, rb, eb);
  // eq. (39), ball rows: g = r_a + R_a p_a - r_b - R_b p_b
  out.g.head<3>() =
      y_a.head<3>() + ra * p_.leading_point_m - y_b.head<3>() - rb * p_.trailing_point_m;
  // d(R p)/dt = R (omega x p) = -R [p]x E angles'  =>  d(R p)/d angles = -R [p]x E
  out.dg_dya.topLeftCorner<3, 3>().setIdentity();
  out.dg_dya.block<3, 3>(0, 3).noalias() = -(ra * skew(p_.leading_point_m)) * ea;
  out.dg_dyb.topLeftCorner<3, 3>() = -Mat3::Identity();
  out.dg_dyb.block<3, 3>(0, 3).noalias() = (rb * skew(p_.trailing_point_m)) * eb;
  if (p_.kind == JointKind::kTowBar) {
    // g = |d| - L with d = -(ball g) the rod from the leading to the towed end; dg/dy = -u^T
    // d(ball g)/dy, u = d / |d| (a zero-length rod has no direction: u = 0, a degenerate setup)
    const Vec3 d = -out.g.head<3>();
    const double length = d.norm();
    const Vec3 u = length > 0 ? Vec3(d / length) : Vec3::Zero();
    out.g(0) = length - p_.length_m;
    out.g.segment<3>(1).setZero();
    out.dg_dya.row(0) = -u.transpose() * out.dg_dya.topRows<3>();
    out.dg_dyb.row(0) = -u.transpose() * out.dg_dyb.topRows<3>();
    out.dg_dya.bottomRows<3>().setZero();
    out.dg_dyb.bottomRows<3>().setZero();
    return;
  }
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
