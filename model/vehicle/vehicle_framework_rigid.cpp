// The framework's rigid axles (rigid_axle.h): axle a's two framework slots h = 6 + 2a, h + 1 are
// its heave and roll against the body. Each wheel is a point mass (half the axle's mass) at its
// centre p(h, phi) with J_v = [I, -[r]x, e_z, dp/dphi] and the carrier's angular velocity
// omega + phi' e_x; the roll inertia beyond the point masses acts on omega_x + phi'.
#include <cmath>

#include "model/tire/tmeasy_tire.h"
#include "model/vehicle/tire_partials.h"
#include "model/vehicle/vehicle_framework.h"

namespace rig::model::vehicle {
namespace {

/// e_x x v
Vec3 roll_cross(const Vec3& v) noexcept { return {0.0, -v.z(), v.y()}; }

}  // namespace

void VehicleFramework::setup_rigid_axles() {
  for (std::size_t a = 0; a < p_.axles.size(); ++a) {
    const AxleParams& ax = p_.axles[a];
    if (ax.kind != AxleKind::kRigid) continue;
    rigid_[a] = true;
    any_rigid_ = true;
    rigid_geometry_[a] =
        rigid_axle_geometry(ax, p_.chassis.cg_height_m, mount_[2 * a], mount_[2 * a + 1]);
    default_suspension_[a] = SpringDamperAxleSuspension(ax, preload_[2 * a], preload_[2 * a + 1]);
    suspension_[a] = &default_suspension_[a];
  }
}

AxleSuspensionForces VehicleFramework::axle_suspension_forces(int axle, const Vector& y,
                                                              const Vector& z) const noexcept {
  const Eigen::Index h = 6 + 2 * static_cast<Eigen::Index>(axle);
  AxleSuspensionForces f;
  suspension_[static_cast<std::size_t>(axle)]->forces(y(h), y(h + 1), z(h), z(h + 1), f);
  return f;
}

AxleSuspensionForces VehicleFramework::axle_suspension_forces(
    int axle, const Vector& y, const Vector& z, const AxleHousingLoad& housing) const noexcept {
  const Eigen::Index h = 6 + 2 * static_cast<Eigen::Index>(axle);
  AxleSuspensionForces f;
  suspension_[static_cast<std::size_t>(axle)]->forces_under_load(y(h), y(h + 1), z(h), z(h + 1),
                                                                 housing, f);
  return f;
}

WheelContact VehicleFramework::rigid_contact(const Mat3& rot, const Vector& y, const Vector& z,
                                             int i) const noexcept {
  if (twisted(i)) return rear_rigid_contact(rot, y, z, i);  // behind the frame's split
  const auto k = static_cast<std::size_t>(i);
  const Eigen::Index h = 6 + 2 * (i / 2);
  const RigidWheelPoint w = rigid_point(i / 2, i % 2, y);
  const Vec3 hub_velocity = Vec3::UnitZ() * z(h) + w.d_droll_m * z(h + 1);
  const double r0 = p_.axles[k / 2].tire.tmeasy.radius_unloaded_m;
  WheelContact c =
      road_.is_plane()
          ? wheel_contact(road_, rot, y.head<3>(), z.segment<3>(0), z.segment<3>(3), w.centre_m,
                          hub_velocity, work_.wheels[k].spin_axis, r0)
          : wheel_contact(work_.wheels[k].road, rot, y.head<3>(), z.segment<3>(0), z.segment<3>(3),
                          w.centre_m, hub_velocity, work_.wheels[k].spin_axis, r0);
  // the contact point is the axle's: the roll rate also moves it about the wheel centre
  const Vec3 extra = z(h + 1) * roll_cross(c.lever_m - w.centre_m);
  c.vx_mps += c.ex.dot(extra);
  c.vy_mps += c.ey.dot(extra);
  c.penetration_rate_mps -= c.normal.dot(extra);
  return c;
}

void VehicleFramework::rigid_mass_matrix(int axle, const Vector& y, Matrix& m) const noexcept {
  if (twisted(2 * axle)) {  // behind the frame's split
    rear_rigid_mass_matrix(axle, y, m);
    return;
  }
  const auto a = static_cast<std::size_t>(axle);
  const Eigen::Index h = 6 + 2 * static_cast<Eigen::Index>(axle);
  const double mw = p_.axles[a].unsprung_mass_kg;
  for (int side = 0; side < 2; ++side) {
    const RigidWheelPoint w = rigid_point(axle, side, y);
    const Vec3& r = w.centre_m;
    const Mat3 rx = skew(r);
    Eigen::Matrix<double, 3, 2> gq;  // d r / d(heave, roll)
    gq << Vec3::UnitZ(), w.d_droll_m;
    // J_v = [I, -[r]x, G]: M += m J_v^T J_v
    m.block<3, 3>(0, 0).diagonal().array() += mw;
    m.block<3, 3>(0, 3) -= mw * rx;
    m.block<3, 3>(3, 0) += mw * rx;
    m.block<3, 3>(3, 3) += mw * rx.transpose() * rx;
    m.block<3, 2>(0, h) += mw * gq;
    m.block<2, 3>(h, 0) += mw * gq.transpose();
    const Eigen::Matrix<double, 3, 2> rxg = rx * gq;  // r x g_j
    m.block<3, 2>(3, h) += mw * rxg;
    m.block<2, 3>(h, 3) += mw * rxg.transpose();
    m.block<2, 2>(h, h) += mw * gq.transpose() * gq;
  }
  // the roll inertia beyond the point masses, on omega_x + roll'
  const double di = rigid_geometry_[a].extra_roll_inertia_kgm2;
  m(3, 3) += di;
  m(3, h + 1) += di;
  m(h + 1, 3) += di;
  m(h + 1, h + 1) += di;
}

void VehicleFramework::rigid_wheel_applied(int i, const Mat3& rot, const Vector& y, const Vector& z,
                                           const Vec3& g, Vec3& ft, Vec3& tr, Vector& q,
                                           AxleHousingLoad& housing) const noexcept {
  if (twisted(i)) {  // behind the frame's split
    rear_rigid_wheel_applied(i, rot, y, z, g, ft, tr, q, housing);
    return;
  }
  const auto k = static_cast<std::size_t>(i);
  const Eigen::Index h = 6 + 2 * (i / 2);
  const Vec3 v = z.segment<3>(0), w = z.segment<3>(3);
  const RigidWheelPoint pt = rigid_point(i / 2, i % 2, y);
  const Vec3& r = pt.centre_m;
  const Vec3 rel = Vec3::UnitZ() * z(h) + pt.d_droll_m * z(h + 1);
  // velocity-dependent acceleration: transport, Coriolis, and the roll's centripetal term
  const Vec3 a0 = w.cross(v) + w.cross(w.cross(r)) + 2.0 * w.cross(rel) +
                  z(h + 1) * z(h + 1) * roll_cross(roll_cross(pt.from_axis_m));
  const CarrierLoad l = carrier_load(i, rot, y, z, g, r, a0);
  const Vec3& f = l.force_n;
  // the carrier's moment summed apart from r x f, unlike the independent wheel's: the rounding
  // of the existing runs is kept
  const Vec3 m_carrier = l.add_to_body(r, ft, tr);
  q(h) += f.z();
  q(h + 1) += pt.d_droll_m.dot(f) + m_carrier.x();
  // the housing's fore-aft load: f holds the transport terms of the wheel's inertia (a0), not
  // its share of the body's own dv/dt (in M): that from the last step's acceleration
  const double dvdt_x = state_.acceleration_mps2.x() - w.cross(v).x();
  housing.force_x_n += f.x() - p_.axles[k / 2].unsprung_mass_kg * dvdt_x;
  housing.moment_y_nm += m_carrier.y();
}

void VehicleFramework::rigid_suspension_jacobians(int axle, const Vector& y, const Vector& z,
                                                  Matrix& dq_dy, Matrix& dq_dz) const noexcept {
  const Eigen::Index h = 6 + 2 * static_cast<Eigen::Index>(axle);
  const AxleSuspensionForces f = axle_suspension_forces(axle, y, z);
  dq_dy.block<2, 2>(h, h) += f.dq_dy;
  dq_dz.block<2, 2>(h, h) += f.dq_dz;
}

void VehicleFramework::rigid_tire_jacobians(int i, const Mat3& rot, const Mat3& e_inv,
                                            const Vector& y, const Vector& z, Matrix& dq_dy,
                                            Matrix& dq_dz) const noexcept {
  // as tire_jacobians, with the axle's two columns: force rows at the wheel centre (J_C^T u;
  // on the roll at the contact point, J_P^T u), velocity rows at the contact (u^T J_P)
  if (twisted(i)) {  // behind the frame's split
    rear_rigid_tire_jacobians(i, rot, e_inv, y, z, dq_dy, dq_dz);
    return;
  }
  const auto k = static_cast<std::size_t>(i);
  const tire::TmeasyParams& t = p_.axles[k / 2].tire.tmeasy;
  const Eigen::Index h = 6 + 2 * (i / 2);
  const WheelContact c = evaluation_contact(rot, y, z, i);
  if (c.penetration_m <= 0) return;
  const RigidWheelPoint pt = rigid_point(i / 2, i % 2, y);
  const Vec3& centre = pt.centre_m;
  const Vec3 roll_col = pt.d_droll_m + roll_cross(c.lever_m - centre);  // d contact / d roll
  const Vec3 e_z = Vec3::UnitZ();
  TirePartials<2> j;
  tire_partials<2>(c, centre, {&e_z, &roll_col}, rot, e_inv, t.vertical_stiffness_npm,
                   tire_damping_nspm(t, work_.wheels[k].tire.characteristic, tire_kinematics(c, i)),
                   j);
  // on the roll, the wheel's force (last step's) on its moving lever: the contact point rises
  // with the centre's height (-height n below it), and d(dp/dphi)/dphi = e_x x (e_x x d)
  const WheelForces& out = work_.wheels[k].out;
  const Vec3 tire_force = out.force_x_n * c.ex + out.force_y_n * c.ey;
  j.dq_dy.row(7) -= roll_cross(c.normal).dot(tire_force) * j.pen_dy.transpose();
  const Vec3 f = tire_force + out.load_n * c.normal;
  j.dq_dy(7, 7) -= pt.from_axis_m.y() * f.y() + pt.from_axis_m.z() * f.z();
  scatter_tire_block<2>(j.dq_dz, {h, h + 1}, dq_dz);
  scatter_tire_block<2>(j.dq_dy, {h, h + 1}, dq_dy);
}

}  // namespace rig::model::vehicle
