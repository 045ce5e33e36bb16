#include "model/vehicle/free_body/free_body.h"

#include <cmath>

namespace rig::model::vehicle {
namespace {

Vec3 vec3(const std::array<double, 3>& a) noexcept { return {a[0], a[1], a[2]}; }

using Mat36 = Eigen::Matrix<double, 3, 6>;

/// J = [I, -[p]x] (the velocity of point p from the speeds [v, omega], own axes) is used by its
/// blocks: products with J and J^T skip its identity and zeros. Each entry of a product with
/// -[p]x sums at most two non-zero terms (one zero per row and column), so it is the same in
/// any order: the partials are bit-identical to the full 3 x 6 products.
Mat3 lever(const Vec3& p) noexcept { return -skew(p); }

/// X J for J = [I, l]: [X, X l].
Mat36 times_j(const Mat3& x, const Mat3& l) noexcept {
  Mat36 out;
  out.leftCols<3>() = x;
  out.rightCols<3>().noalias() = x * l;
  return out;
}

/// out += J^T X for J = [I, l] (J^T = [I; l^T]); X: 3 x cols.
template <int Cols, typename Out>
void add_jt_times(const Mat3& l, const Eigen::Matrix<double, 3, Cols>& x, Out&& out) noexcept {
  out.template topRows<3>() += x;
  out.template bottomRows<3>().noalias() += l.transpose() * x;
}

/// d(s)/d(y) = diag(R^T, E): from coordinate to speed-space displacements (K of y' = K^-1 z).
void times_k(const Mat6& dq_ds, const Mat3& rot, const Mat3& e, Mat6& dq_dy) noexcept {
  dq_dy.leftCols<3>() = dq_ds.leftCols<3>() * rot.transpose();
  dq_dy.rightCols<3>() = dq_ds.rightCols<3>() * e;
}

/// The mount's rates in chassis axes with its stops' (off its stops: the constant springs').
Mat3 rates(const Mount& m, const MountForce& f) noexcept {
  return f.rate_stiffness == m.stiffness ? m.stiffness_matrix
                                         : chassis_axes_matrix(m, f.rate_stiffness);
}

}  // namespace

FreeBody::FreeBody(const FreeBodyParams& p, const road::Road& road, VehicleState& state,
                   const VehicleWorkspace& work, int slot, const PredictedChassis& chassis)
    : MountedBody<6>(p, road, state, work, slot, chassis) {
  mount_count_ = static_cast<int>(std::min<std::size_t>(p.mounts.size(), kMaxMounts));
  const Vec3 position = vec3(p.position_m);
  for (int i = 0; i < mount_count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    mounts_[k] = make_mount(p.mounts[k], position, p.through_margin_m);
  }
  inertia_ = vec3(p.inertia_kgm2);
  crank_axis_ = vec3(p.crankshaft_axis).normalized();
}

FreeBody::Vector& FreeBody::coordinates() noexcept { return state_.free_body_y[slot()]; }
FreeBody::Vector& FreeBody::speeds() noexcept { return state_.free_body_z[slot()]; }

void FreeBody::kinematics_inverse(const Vector& y, Matrix& k_inv) const noexcept {
  k_inv.setZero();
  k_inv.topLeftCorner<3, 3>() = body_to_road(y(3), y(4), y(5));
  k_inv.bottomRightCorner<3, 3>() = euler_rates_from_body_rates(y(4), y(5));
}

void FreeBody::mass_matrix(const Vector& y, Matrix& m) const noexcept {
  (void)y;
  m.setZero();
  m.diagonal() << p_.mass_kg, p_.mass_kg, p_.mass_kg, inertia_;
}

double FreeBody::reaction_torque_nm() const noexcept {
  return p_.kind == FreeBodyKind::kEngine ? work_.engine_torque_nm : 0.0;
}

const FreeBody::BodySide& FreeBody::body_side(const Vector& y, const Vector& z) const noexcept {
  InputKey<25>::Values in;
  std::size_t at = put(in, 0, y.data(), 6);
  at = put(in, at, z.data(), 6);
  const ChassisInputs chassis = chassis_inputs();
  put(in, at, chassis.data(), chassis.size());
  if (body_key_.hit(in)) return body_side_;
  body_side_.chassis = chassis_pose();
  body_side_.body = rigid_pose(y, z);
  for (int i = 0; i < mount_count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    body_side_.forces[k] = mount_force(mounts_[k], body_side_.chassis, body_side_.body);
  }
  return body_side_;
}

const FreeBody::ChassisSide& FreeBody::chassis_side(const RigidPose& chassis) const noexcept {
  InputKey<30>::Values in;
  std::size_t at = put(in, 0, chassis.rot.data(), 9);
  at = put(in, at, chassis.position_m.data(), 3);
  at = put(in, at, chassis.velocity_mps.data(), 3);
  at = put(in, at, chassis.rate_radps.data(), 3);
  at = put(in, at, state_.free_body_y[slot()].data(), 6);
  put(in, at, state_.free_body_z[slot()].data(), 6);
  if (chassis_side_key_.hit(in)) return chassis_side_;
  chassis_side_.body = rigid_pose(state_.free_body_y[slot()], state_.free_body_z[slot()]);
  for (int i = 0; i < mount_count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    chassis_side_.forces[k] = mount_force(mounts_[k], chassis, chassis_side_.body);
  }
  return chassis_side_;
}

void FreeBody::applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept {
  const BodySide& side = body_side(y, z);
  const RigidPose& chassis = side.chassis;
  const RigidPose& body = side.body;
  const Vec3& v = body.velocity_mps;
  const Vec3& w = body.rate_radps;
  Vec3 force = p_.mass_kg * (body.rot.transpose() * road_.gravity_mps2() - w.cross(v));
  Vec3 moment = -w.cross(inertia_.cwiseProduct(w)) - reaction_torque_nm() * crank_axis_;
  const Mat3 to_body = body.rot.transpose() * chassis.rot;
  for (int i = 0; i < mount_count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec3 f = to_body * side.forces[k].force_n;
    force += f;
    moment += mounts_[k].body_point.cross(f);
  }
  q << force, moment;
}

bool FreeBody::force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                               Matrix& dq_dz) const noexcept {
  const BodySide& side = body_side(y, z);
  const RigidPose& chassis = side.chassis;
  const RigidPose& body = side.body;
  const Mat3 a = chassis.rot.transpose() * body.rot;  // body axes -> chassis axes
  const Mat3 wc = skew(chassis.rate_radps);
  Mat6 dq_ds = Mat6::Zero();
  dq_dz.setZero();
  // gravity turns with the body: d(m R^T g)/d theta = [m R^T g]x
  dq_ds.block<3, 3>(0, 3) = skew(p_.mass_kg * (body.rot.transpose() * road_.gravity_mps2()));
  for (int i = 0; i < mount_count_; ++i) {
    const Mount& m = mounts_[static_cast<std::size_t>(i)];
    const MountForce& mf = side.forces[static_cast<std::size_t>(i)];
    const Mat3 l = lever(m.body_point);  // J = [I, l]
    const Mat36 aj = times_j(a, l);      // d(deflection)/ds, chassis axes
    const Mat3 k = rates(m, mf);
    const Mat3& c = m.damping_matrix;
    // d(deflection rate)/ds: the chassis turning under the body, the body's own velocity turning
    Mat36 dd_ds = -wc * aj;
    dd_ds.rightCols<3>() -= a * skew(body.velocity_mps + body.rate_radps.cross(m.body_point));
    const Mat36 df_ds = -k * aj - c * dd_ds;  // chassis axes
    const Vec3 f_body = a.transpose() * mf.force_n;
    const Mat36 df_body = a.transpose() * df_ds;
    add_jt_times(l, df_body, dq_ds);                            // J^T A^T dF/ds
    add_jt_times(l, Mat3(skew(f_body)), dq_ds.rightCols<3>());  // the force turns with it
    dq_dz.noalias() -= aj.transpose() * c * aj;
  }
  times_k(dq_ds, body.rot, body_rates_from_euler_rates(y(4), y(5)), dq_dy);
  return true;
}

Vec6 FreeBody::chassis_load(const RigidPose& chassis) const noexcept {
  const ChassisSide& side = chassis_side(chassis);
  const RigidPose& body = side.body;
  Vec3 force = Vec3::Zero();
  // the drive torque's reaction: +T about the crank on the chassis (through the drive line)
  Vec3 moment = reaction_torque_nm() * (chassis.rot.transpose() * (body.rot * crank_axis_));
  for (int i = 0; i < mount_count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec3 f = -side.forces[k].force_n;
    force += f;
    moment += mounts_[k].chassis_point.cross(f);
  }
  Vec6 q;
  q << force, moment;
  return q;
}

void FreeBody::chassis_jacobians(const RigidPose& chassis, Mat6& dq_ds,
                                 Mat6& dq_dz) const noexcept {
  const ChassisSide& side = chassis_side(chassis);
  const RigidPose& body = side.body;
  const Mat3 rt = chassis.rot.transpose();
  const Mat3 wc = skew(chassis.rate_radps);
  const Vec3 torque = reaction_torque_nm() * (rt * (body.rot * crank_axis_));
  dq_ds.block<3, 3>(3, 3) += skew(torque);  // the reaction turns with the chassis
  for (int i = 0; i < mount_count_; ++i) {
    const Mount& m = mounts_[static_cast<std::size_t>(i)];
    const MountForce& mf = side.forces[static_cast<std::size_t>(i)];
    const Vec3 pb = body.position_m + body.rot * m.body_point;
    const Vec3 vb = body.rot * (body.velocity_mps + body.rate_radps.cross(m.body_point));
    const Vec3 body_point = rt * (pb - chassis.position_m);  // = rel + chassis point
    const Mat3 ld = lever(body_point);                       // d(deflection) = -jd ds, jd = [I, ld]
    Mat36 dd_ds;
    dd_ds.leftCols<3>() = wc;
    dd_ds.rightCols<3>() = skew(rt * vb) - wc * skew(body_point);
    const Mat3 k = rates(m, mf);
    const Mat3& c = m.damping_matrix;
    const Mat3 lc = lever(m.chassis_point);  // the chassis point's J = [I, lc]
    // the chassis gets F = K d + C d' (minus the force on the body)
    Mat36 jd;
    jd << Mat3::Identity(), ld;
    const Mat36 df = -k * jd + c * dd_ds;
    add_jt_times(lc, df, dq_ds);
    // dq_dz -= J_c^T C jd = [T, T ld] with T = J_c^T C
    Eigen::Matrix<double, 6, 3> t;
    t.topRows<3>() = c;
    t.bottomRows<3>().noalias() = lc.transpose() * c;
    dq_dz.leftCols<3>() -= t;
    dq_dz.rightCols<3>().noalias() -= t * ld;
  }
}

double FreeBody::beyond_stop_m(const RigidPose& chassis) const noexcept {
  const RigidPose body = rigid_pose(state_.free_body_y[slot()], state_.free_body_z[slot()]);
  double beyond = -1e9;
  for (int i = 0; i < mount_count_; ++i)
    beyond = std::max(
        beyond, mount_force(mounts_[static_cast<std::size_t>(i)], chassis, body).beyond_stop_m);
  return beyond;
}

MountForce FreeBody::mount_force_now(int i) const noexcept {
  const RigidPose body = rigid_pose(state_.free_body_y[slot()], state_.free_body_z[slot()]);
  return mount_force(mounts_[static_cast<std::size_t>(i)],
                     rigid_pose(state_.framework_y, state_.framework_z), body);
}

RelativeMotion relative_motion(const RigidPose& chassis, const RigidPose& body,
                               const Vec3& design_position_m) noexcept {
  RelativeMotion out;
  const Mat3 rt = chassis.rot.transpose();
  const Vec3 rel = rt * (body.position_m - chassis.position_m);
  out.position_m = rel - design_position_m;
  const Mat3 a = rt * body.rot;  // = Rz(yaw) Ry(pitch) Rx(roll) of the relative attitude
  out.angles_rad = Vec3(std::atan2(a(2, 1), a(2, 2)), -std::asin(std::clamp(a(2, 0), -1.0, 1.0)),
                        std::atan2(a(1, 0), a(0, 0)));
  const Vec3 vb = body.rot * body.velocity_mps;
  const Vec3 vc = chassis.rot * chassis.velocity_mps;
  out.velocity_mps = rt * (vb - vc) - chassis.rate_radps.cross(rel);
  out.rate_radps = a * body.rate_radps - chassis.rate_radps;
  return out;
}

}  // namespace rig::model::vehicle
