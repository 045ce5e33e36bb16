// The framework's frame torsion (frame/frame_torsion.h): the twist theta, stored last in y and z,
// is the rear part's roll against the chassis about the torsion axis. The rear part's share of
// the sprung mass is a point mass at its CG c(theta) plus its roll inertia on omega_x + theta';
// the independent wheels behind the split are point masses at r(theta) with
// J_v = [I, -[r]x, Rx(theta) e_s, e_x x (r - a)] and their carriers turn with omega + theta' e_x.
#include <array>
#include <cmath>

#include "model/tire/tmeasy_tire.h"
#include "model/tire/vertical_tire_force.h"
#include "model/vehicle/point_mass_columns.h"
#include "model/vehicle/tire_partials.h"
#include "model/vehicle/vehicle_framework.h"

namespace rig::model::vehicle {

void VehicleFramework::setup_frame() {
  if (!p_.frame.enabled) return;
  frame_ = frame_geometry(p_.frame, p_.chassis.cg_height_m);
  twist_ = n_ - 1;
  for (std::size_t a = 0; a < p_.axles.size(); ++a)
    rear_[a] = p_.axles[a].position_x_m < frame_.split_x_m;
}

VehicleFramework::RearWheelPose VehicleFramework::rear_wheel_pose(int i,
                                                                  const Vector& y) const noexcept {
  const TwistRotation rx = twist_rotation(y);
  const TwistedPoint c = twisted_point(frame_, wheel_centre(i, y(6 + i)), rx);
  return {c.point_m, rx * hub_axis(i), c.d_dtwist_m,
          rx * work_.wheels[static_cast<std::size_t>(i)].spin_axis};
}

void VehicleFramework::frame_mass_matrix(const Vector& y, Matrix& m) const noexcept {
  const double mr = frame_.rear_mass_kg;
  const TwistedPoint c = twisted_point(frame_, frame_.rear_cg_m, twist_rotation(y));
  // the chassis holds the rear part's mass at its design CG c0: move it to c(theta)
  const Mat3 rx = skew(c.point_m), rx0 = skew(frame_.rear_cg_m);
  m.block<3, 3>(0, 3) -= mr * (rx - rx0);
  m.block<3, 3>(3, 0) += mr * (rx - rx0);
  m.block<3, 3>(3, 3) += mr * (rx.transpose() * rx - rx0.transpose() * rx0);
  const Vec3 rot_col =
      mr * c.point_m.cross(c.d_dtwist_m) + frame_.rear_roll_inertia_kgm2 * Vec3::UnitX();
  m.block<3, 1>(0, twist_) += mr * c.d_dtwist_m;
  m.block<1, 3>(twist_, 0) += mr * c.d_dtwist_m.transpose();
  m.block<3, 1>(3, twist_) += rot_col;
  m.block<1, 3>(twist_, 3) += rot_col.transpose();
  m(twist_, twist_) += mr * c.d_dtwist_m.squaredNorm() + frame_.rear_roll_inertia_kgm2;
}

void VehicleFramework::rear_wheel_mass_matrix(int i, const Vector& y, Matrix& m) const noexcept {
  const double mw = p_.axles[static_cast<std::size_t>(i / 2)].unsprung_mass_kg;
  const RearWheelPose w = rear_wheel_pose(i, y);
  add_point_mass<2>(m, mw, w.centre_m, {&w.hub_axis, &w.d_dtwist_m}, {6 + i, twist_});
}

WheelContact VehicleFramework::rear_wheel_contact(const Mat3& rot, const Vector& y, const Vector& z,
                                                  int i) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  const RearWheelPose w = rear_wheel_pose(i, y);
  const double theta_rate = z(twist_);
  const Vec3 hub_velocity = w.hub_axis * z(6 + i) + w.d_dtwist_m * theta_rate;
  const double r0 = p_.axles[k / 2].tire.tmeasy.radius_unloaded_m;
  WheelContact c = road_.is_plane()
                       ? wheel_contact(road_, rot, y.head<3>(), z.segment<3>(0), z.segment<3>(3),
                                       w.centre_m, hub_velocity, w.spin_axis, r0)
                       : wheel_contact(work_.wheels[k].road, rot, y.head<3>(), z.segment<3>(0),
                                       z.segment<3>(3), w.centre_m, hub_velocity, w.spin_axis, r0);
  // the carrier turns with the rear part: the twist rate also moves the contact point about
  // the wheel centre
  const Vec3 extra = theta_rate * ex_cross(c.lever_m - w.centre_m);
  c.vx_mps += c.ex.dot(extra);
  c.vy_mps += c.ey.dot(extra);
  c.penetration_rate_mps -= c.normal.dot(extra);
  return c;
}

void VehicleFramework::rear_wheel_applied(int i, const Mat3& rot, const Vector& y, const Vector& z,
                                          const Vec3& g, Vec3& ft, Vec3& tr,
                                          Vector& q) const noexcept {
  const Vec3 v = z.segment<3>(0), w = z.segment<3>(3);
  const RearWheelPose pose = rear_wheel_pose(i, y);
  const Vec3& r = pose.centre_m;
  const double sd = z(6 + i), td = z(twist_);
  const Vec3 rel = pose.hub_axis * sd + pose.d_dtwist_m * td;
  // transport, Coriolis, the twist's Coriolis on the hub rate and its centripetal term
  const Vec3 a0 = w.cross(v) + w.cross(w.cross(r)) + 2.0 * w.cross(rel) +
                  2.0 * td * ex_cross(pose.hub_axis * sd) + td * td * ex_cross(pose.d_dtwist_m);
  const CarrierLoad l = carrier_load(i, rot, y, z, g, r, a0);
  const Vec3& f = l.force_n;
  const Vec3 m_carrier = l.add_to_body(r, ft, tr);
  q(6 + i) = pose.hub_axis.dot(f) - l.tire.suspension_n;
  q(twist_) += pose.d_dtwist_m.dot(f) + m_carrier.x();
}

void VehicleFramework::frame_applied(const Vector& y, const Vector& z, const Vec3& g, Vec3& ft,
                                     Vec3& tr, Vector& q) const noexcept {
  const Vec3 v = z.segment<3>(0), w = z.segment<3>(3);
  const double mr = frame_.rear_mass_kg, td = z(twist_);
  const Vec3& c0 = frame_.rear_cg_m;
  const TwistedPoint c = twisted_point(frame_, c0, twist_rotation(y));
  // the rear part's point mass at c(theta) instead of the chassis' c0 (same terms at theta = 0)
  const Vec3 a0 = w.cross(v) + w.cross(w.cross(c.point_m)) + 2.0 * td * w.cross(c.d_dtwist_m) +
                  td * td * ex_cross(c.d_dtwist_m);
  const Vec3 f = mr * (g - a0);
  const Vec3 f0 = mr * (g - w.cross(v) - w.cross(w.cross(c0)));
  ft += f - f0;
  tr += c.point_m.cross(f) - c0.cross(f0);
  q(twist_) += c.d_dtwist_m.dot(f) - vehicle::torsion_moment_nm(frame_, y(twist_), td);
}

void VehicleFramework::rear_tire_jacobians(int i, const Mat3& rot, const Mat3& e_inv,
                                           const Vector& y, const Vector& z, Matrix& dq_dy,
                                           Matrix& dq_dz) const noexcept {
  // as tire_jacobians, with the twist column: on it the contact force's moment about the
  // torsion axis, e_x . ((contact - a) x u) = (e_x x (contact - a)) . u
  const auto k = static_cast<std::size_t>(i);
  const tire::TmeasyParams& t = p_.axles[k / 2].tire.tmeasy;
  const Eigen::Index h = 6 + i;
  const WheelContact c = evaluation_contact(rot, y, z, i);
  if (c.penetration_m <= 0) return;
  const RearWheelPose pose = rear_wheel_pose(i, y);
  const Vec3 twist_col = pose.d_dtwist_m + ex_cross(c.lever_m - pose.centre_m);
  TirePartials<2> j;
  tire_partials<2>(
      c, pose.centre_m, {&pose.hub_axis, &twist_col}, rot, e_inv, t.vertical_stiffness_npm,
      tire_damping_nspm(t, work_.wheels[k].tire.characteristic, tire_kinematics(c, i)), j);
  scatter_tire_block<2>(j.dq_dz, {h, twist_}, dq_dz);
  scatter_tire_block<2>(j.dq_dy, {h, twist_}, dq_dy);
}

void VehicleFramework::frame_jacobians(Matrix& dq_dy, Matrix& dq_dz) const noexcept {
  // the frame's spring-damper on the twist (a relative coordinate: on theta only)
  dq_dy(twist_, twist_) -= frame_.stiffness_nmprad;
  dq_dz(twist_, twist_) -= frame_.damping_nmsprad;
}

double VehicleFramework::torsion_moment_nm(const Vector& y, const Vector& z) const noexcept {
  return twist_ < 0 ? 0.0 : vehicle::torsion_moment_nm(frame_, y(twist_), z(twist_));
}

}  // namespace rig::model::vehicle

namespace rig::model::vehicle {

// ---- rigid axles behind the split: the axle's heave and roll against the rear part, the whole
// axle twisted with it (p = a + Rx(theta)(p_axle(h, phi) - a)); its columns Rx e_z, Rx dp/dphi
// and e_x x (p - a), the carrier turning with omega + (phi' + theta') e_x ----

VehicleFramework::RearRigidPoint VehicleFramework::rear_rigid_point(
    int i, const Vector& y) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  const TwistRotation rx = twist_rotation(y);
  const RigidWheelPoint w = rigid_point(i / 2, i % 2, y);
  const TwistedPoint c = twisted_point(frame_, w.centre_m, rx);
  return {c.point_m,    rx * Vec3::UnitZ(), rx * w.d_droll_m,
          c.d_dtwist_m, rx * w.from_axis_m, rx * work_.wheels[k].spin_axis};
}

void VehicleFramework::rear_rigid_mass_matrix(int axle, const Vector& y, Matrix& m) const noexcept {
  const auto a = static_cast<std::size_t>(axle);
  const Eigen::Index h = 6 + 2 * static_cast<Eigen::Index>(axle);
  const double mw = p_.axles[a].unsprung_mass_kg;
  for (int side = 0; side < 2; ++side) {
    const RearRigidPoint w = rear_rigid_point(2 * axle + side, y);
    add_point_mass<3>(m, mw, w.centre_m, {&w.d_dheave, &w.d_droll_m, &w.d_dtwist_m},
                      {h, h + 1, twist_});
  }
  // the roll inertia beyond the point masses, on omega_x + roll' + twist'
  const double di = rigid_geometry_[a].extra_roll_inertia_kgm2;
  const Eigen::Index r[3] = {3, h + 1, twist_};
  for (const Eigen::Index j : r)
    for (const Eigen::Index l : r) m(j, l) += di;
}

WheelContact VehicleFramework::rear_rigid_contact(const Mat3& rot, const Vector& y, const Vector& z,
                                                  int i) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  const Eigen::Index h = 6 + 2 * (i / 2);
  const RearRigidPoint w = rear_rigid_point(i, y);
  const Vec3 hub_velocity = w.d_dheave * z(h) + w.d_droll_m * z(h + 1) + w.d_dtwist_m * z(twist_);
  const double r0 = p_.axles[k / 2].tire.tmeasy.radius_unloaded_m;
  WheelContact c = road_.is_plane()
                       ? wheel_contact(road_, rot, y.head<3>(), z.segment<3>(0), z.segment<3>(3),
                                       w.centre_m, hub_velocity, w.spin_axis, r0)
                       : wheel_contact(work_.wheels[k].road, rot, y.head<3>(), z.segment<3>(0),
                                       z.segment<3>(3), w.centre_m, hub_velocity, w.spin_axis, r0);
  const Vec3 extra = (z(h + 1) + z(twist_)) * ex_cross(c.lever_m - w.centre_m);
  c.vx_mps += c.ex.dot(extra);
  c.vy_mps += c.ey.dot(extra);
  c.penetration_rate_mps -= c.normal.dot(extra);
  return c;
}

void VehicleFramework::rear_rigid_wheel_applied(int i, const Mat3& rot, const Vector& y,
                                                const Vector& z, const Vec3& g, Vec3& ft, Vec3& tr,
                                                Vector& q,
                                                AxleHousingLoad& housing) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  const Eigen::Index h = 6 + 2 * (i / 2);
  const Vec3 v = z.segment<3>(0), w = z.segment<3>(3);
  const RearRigidPoint pt = rear_rigid_point(i, y);
  const Vec3& r = pt.centre_m;
  const double td = z(twist_), rd = z(h + 1);
  const Vec3 rel = pt.d_dheave * z(h) + pt.d_droll_m * rd + pt.d_dtwist_m * td;
  // transport, Coriolis; the roll's and the twist's centripetal and cross terms (both about e_x)
  const Vec3 a0 = w.cross(v) + w.cross(w.cross(r)) + 2.0 * w.cross(rel) +
                  rd * rd * ex_cross(ex_cross(pt.from_axis_m)) + td * td * ex_cross(pt.d_dtwist_m) +
                  2.0 * td * ex_cross(pt.d_dheave * z(h) + pt.d_droll_m * rd);
  const CarrierLoad l = carrier_load(i, rot, y, z, g, r, a0);
  const Vec3& f = l.force_n;
  const Vec3 m_carrier = l.add_to_body(r, ft, tr);
  q(h) += pt.d_dheave.dot(f);
  q(h + 1) += pt.d_droll_m.dot(f) + m_carrier.x();
  q(twist_) += pt.d_dtwist_m.dot(f) + m_carrier.x();
  // the leaf's housing load as on the front part (rigid_wheel_applied); the twist turns about
  // x, so x stays the rear part's fore-aft and the pitch moment is taken in the chassis' axes
  // (the twist is a few centiradians: cos 0.03 = 0.9996)
  const double dvdt_x = state_.acceleration_mps2.x() - w.cross(v).x();
  housing.force_x_n += f.x() - p_.axles[k / 2].unsprung_mass_kg * dvdt_x;
  housing.moment_y_nm += m_carrier.y();
}

namespace {

using Row9 = Eigen::Matrix<double, 9, 1>;
using Block9 = Eigen::Matrix<double, 9, 9>;

/// The wheel's force (last step's) on its moving levers, as rigid_tire_jacobians: the contact
/// point's height on roll and twist; the second derivatives of p in roll and twist, both about
/// e_x (e_x x (e_x x d) . f = -(d_y f_y + d_z f_z)); the heave axis turning with the twist.
void add_moving_lever_partials(const WheelForces& out, const WheelContact& c,
                               const Vec3& from_axis_m, const Vec3& d_dtwist_m,
                               const Vec3& d_dheave, const Row9& bk, Block9& dy_block) noexcept {
  const Vec3 tire_force = out.force_x_n * c.ex + out.force_y_n * c.ey;
  const double lever = ex_cross(c.normal).dot(tire_force);
  dy_block.row(7) -= lever * bk.transpose();
  dy_block.row(8) -= lever * bk.transpose();
  const Vec3 f = tire_force + out.load_n * c.normal;
  const double roll2 = from_axis_m.y() * f.y() + from_axis_m.z() * f.z();
  const double twist2 = d_dtwist_m.z() * f.y() - d_dtwist_m.y() * f.z();  // p - a
  dy_block(7, 7) -= roll2;
  dy_block(7, 8) -= roll2;
  dy_block(8, 7) -= roll2;
  dy_block(8, 8) -= twist2;
  dy_block(6, 8) += ex_cross(d_dheave).dot(f);
  dy_block(8, 6) += ex_cross(d_dheave).dot(f);  // the twist's lever moves with the heave
}

}  // namespace

void VehicleFramework::rear_rigid_tire_jacobians(int i, const Mat3& rot, const Mat3& e_inv,
                                                 const Vector& y, const Vector& z, Matrix& dq_dy,
                                                 Matrix& dq_dz) const noexcept {
  // as rigid_tire_jacobians with the twist's column (the contact force's moment about the axis)
  const auto k = static_cast<std::size_t>(i);
  const tire::TmeasyParams& t = p_.axles[k / 2].tire.tmeasy;
  const Eigen::Index h = 6 + 2 * (i / 2);
  const WheelContact c = evaluation_contact(rot, y, z, i);
  if (c.penetration_m <= 0) return;
  const RearRigidPoint pt = rear_rigid_point(i, y);
  const Vec3 about_centre = ex_cross(c.lever_m - pt.centre_m);
  const Vec3 roll_col = pt.d_droll_m + about_centre;
  const Vec3 twist_col = pt.d_dtwist_m + about_centre;
  TirePartials<3> j;
  tire_partials<3>(
      c, pt.centre_m, {&pt.d_dheave, &roll_col, &twist_col}, rot, e_inv, t.vertical_stiffness_npm,
      tire_damping_nspm(t, work_.wheels[k].tire.characteristic, tire_kinematics(c, i)), j);
  add_moving_lever_partials(work_.wheels[k].out, c, pt.from_axis_m, pt.d_dtwist_m, pt.d_dheave,
                            j.pen_dy, j.dq_dy);
  const std::array<Eigen::Index, 3> idx{h, h + 1, twist_};
  scatter_tire_block<3>(j.dq_dz, idx, dq_dz);
  scatter_tire_block<3>(j.dq_dy, idx, dq_dy);
}

}  // namespace rig::model::vehicle
