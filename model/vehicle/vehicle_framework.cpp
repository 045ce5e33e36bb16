#include "model/vehicle/vehicle_framework.h"

#include <cmath>

#include "model/tire/tmeasy_tire.h"
#include "model/tire/vertical_tire_force.h"
#include "model/vehicle/free_body/free_bodies.h"
#include "model/vehicle/tire_partials.h"

namespace rig::model::vehicle {

VehicleFramework::VehicleFramework(const VehicleParams& p, VehicleState& state,
                                   const VehicleWorkspace& work)
    : p_(p),
      state_(state),
      work_(work),
      road_(p.road),
      wheel_count_(2 * static_cast<int>(p.axles.size())),
      n_(6 + 2 * static_cast<Eigen::Index>(p.axles.size()) + (p.frame.enabled ? 1 : 0)),
      contacts_(n_),
      shares_(axle_shares(p)) {
  const double g = p.road.gravity_mps2;
  const auto& c = p.chassis;
  inertia_ << c.inertia_kgm2[0], 0, -c.inertia_xz_kgm2, 0, c.inertia_kgm2[1], 0, -c.inertia_xz_kgm2,
      0, c.inertia_kgm2[2];
  total_mass_kg_ = c.mass_kg;
  // Static loads of the sprung mass on the springs (heave + pitch of a rigid body on linear
  // springs; the lever rule for two axles; a load-sharing bogie one spring): the springs are
  // preloaded so that the design position is at zero hub travel.
  const Eigen::Vector2d heave_pitch = static_heave_pitch(p, shares_, support_load_n_);
  for (int i = 0; i < wheel_count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const auto& a = p.axles[k / 2];
    axle_of_[k] = i / 2;
    total_mass_kg_ += a.unsprung_mass_kg;
    const AxleShare& sh = shares_[k / 2];
    preload_[k] =
        sh.group < 0
            ? a.spring_stiffness_npm * (heave_pitch(0) - a.position_x_m * heave_pitch(1))
            : sh.weight * sh.group_rate_npm * (heave_pitch(0) - sh.group_x_m * heave_pitch(1));
    const double tire_load = preload_[k] + a.unsprung_mass_kg * g;
    const double centre_height =
        a.tire.tmeasy.radius_unloaded_m - tire_load / a.tire.tmeasy.vertical_stiffness_npm;
    mount_[k] =
        Vec3(a.position_x_m, (i % 2 == 0 ? 0.5 : -0.5) * a.track_m, centre_height - c.cg_height_m);
    // Rill 2011 sec. 3.2: probes at 0.1 r_0 fore and aft, 0.3 B left and right
    probes_[k] = {0.1 * a.tire.tmeasy.radius_unloaded_m, 0.3 * a.tire.tmeasy.bore.contact_width_m};
  }
  setup_rigid_axles();
  setup_frame();
}

Vec3 VehicleFramework::wheel_centre(int i, double s) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  const WheelWork& w = work_.wheels[k];
  const double ds = s - w.hub_travel_m;
  return mount_[k] + Vec3(w.hub_x_m + w.hub_dx_ds * ds, w.hub_y_m + w.hub_dy_ds * ds, s);
}

Vec3 VehicleFramework::hub_axis(int i) const noexcept {
  const WheelWork& w = work_.wheels[static_cast<std::size_t>(i)];
  return {w.hub_dx_ds, w.hub_dy_ds, 1.0};
}

void VehicleFramework::kinematics_inverse(const Vector& y, Matrix& k_inv) const noexcept {
  k_inv.setIdentity(n_, n_);
  k_inv.block<3, 3>(0, 0) = body_to_road(y(3), y(4), y(5));
  k_inv.block<3, 3>(3, 3) = euler_rates_from_body_rates(y(4), y(5));
}

void VehicleFramework::mass_matrix(const Vector& y, Matrix& m) const noexcept {
  m.setZero(n_, n_);
  m.block<3, 3>(0, 0).diagonal().setConstant(p_.chassis.mass_kg);
  m.block<3, 3>(3, 3) = inertia_;
  for (int i = 0; i < wheel_count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (rigid_[k / 2]) {
      if (i % 2 == 0) rigid_mass_matrix(i / 2, y, m);
      continue;
    }
    if (twisted(i)) {
      rear_wheel_mass_matrix(i, y, m);
      continue;
    }
    const double mw = p_.axles[k / 2].unsprung_mass_kg;
    const Vec3 r = wheel_centre(i, y(6 + i));
    const Vec3 es = hub_axis(i);
    const Mat3 rx = skew(r);
    const Eigen::Index h = 6 + i;
    // J_v = [I, -[r]x, e_s]: M += m J_v^T J_v
    m.block<3, 3>(0, 0).diagonal().array() += mw;
    m.block<3, 3>(0, 3) -= mw * rx;
    m.block<3, 3>(3, 0) += mw * rx;  // (-[r]x)^T = [r]x
    m.block<3, 3>(3, 3) += mw * rx.transpose() * rx;
    m.block<3, 1>(0, h) += mw * es;
    m.block<1, 3>(h, 0) += mw * es.transpose();
    const Vec3 rxe = r.cross(es);
    m.block<3, 1>(3, h) += mw * rxe;
    m.block<1, 3>(h, 3) += mw * rxe.transpose();
    m(h, h) += mw * es.squaredNorm();
  }
  if (twist_ >= 0) frame_mass_matrix(y, m);
}

WheelContact VehicleFramework::contact(const Vector& y, const Vector& z, int i) const noexcept {
  return contact(body_to_road(y(3), y(4), y(5)), y, z, i);
}

WheelForces VehicleFramework::wheel_forces(const Vector& y, const Vector& z, int i) const noexcept {
  return wheel_forces(body_to_road(y(3), y(4), y(5)), y, z, i);
}

WheelContact VehicleFramework::contact(const Mat3& rot, const Vector& y, const Vector& z,
                                       int i) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  if (rigid_[k / 2]) return rigid_contact(rot, y, z, i);
  if (twisted(i)) return rear_wheel_contact(rot, y, z, i);
  const double r0 = p_.axles[k / 2].tire.tmeasy.radius_unloaded_m;
  if (road_.is_plane()) {
    return wheel_contact(road_, rot, y.head<3>(), z.segment<3>(0), z.segment<3>(3),
                         wheel_centre(i, y(6 + i)), hub_axis(i) * z(6 + i),
                         work_.wheels[k].spin_axis, r0);
  }
  return wheel_contact(work_.wheels[k].road, rot, y.head<3>(), z.segment<3>(0), z.segment<3>(3),
                       wheel_centre(i, y(6 + i)), hub_axis(i) * z(6 + i), work_.wheels[k].spin_axis,
                       r0);
}

LocalRoadPlane VehicleFramework::road_plane(const Mat3& rot, const Vector& y, const Vector& z,
                                            int i, double lookahead_s,
                                            ProbeHints& hints) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  const Vec3 r = twisted(i)      ? (rigid_[k / 2] ? rear_rigid_point(i, y).centre_m
                                                  : rear_wheel_pose(i, y).centre_m)
                 : rigid_[k / 2] ? rigid_point(i / 2, i % 2, y).centre_m
                                 : wheel_centre(i, y(6 + i));
  const Vec3 velocity = rot * (z.segment<3>(0) + z.segment<3>(3).cross(r));  // road frame
  const Vec3 centre = y.head<3>() + rot * r + lookahead_s * velocity;
  // behind the frame's split the spin axis turns with the twist (rigid or independent alike)
  const Vec3 spin = rot * (twisted(i) ? twist_rotation(y) * work_.wheels[k].spin_axis
                                      : work_.wheels[k].spin_axis);
  const Vec3 heading = spin.cross(Vec3::UnitZ()).normalized();
  const Vec3 down = spin.cross(heading);  // in the wheel plane, at right angles to the heading
  const double r0 = p_.axles[k / 2].tire.tmeasy.radius_unloaded_m;
  return local_road_plane(road_, centre + r0 * down, heading, probes_[k], i % 2 == 1, hints);
}

WheelForces VehicleFramework::wheel_forces(const Mat3& rot, const Vector& y, const Vector& z,
                                           int i) const noexcept {
  return wheel_forces(contact(rot, y, z, i), y, z, i);
}

WheelForces VehicleFramework::wheel_forces(const WheelContact& c, const Vector& y, const Vector& z,
                                           int i) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  const AxleParams& a = p_.axles[k / 2];
  const tire::TmeasyParams& t = a.tire.tmeasy;
  const tire::TireCharacteristic& ch = work_.wheels[k].tire.characteristic;
  WheelForces out;
  out.load_n = tire::vertical_tire_force(t.vertical_stiffness_npm, t.vertical_damping_nspm,
                                         c.penetration_m, c.penetration_rate_mps)
                   .force_n;
  // Tire forces through the deflection states (eqs. 22, 24, 26) with the newest x_e, y_e, w.
  const tire::TireKinematics kin = tire_kinematics(c, i);
  const tire::TireSlip slip = tire::slip_of(ch, kin, t.velocity_floor_mps);
  out.tire = kin;
  out.slip_x = slip.slip_x;
  out.slip_y = slip.slip_y;
  if (out.load_n > 0) {  // lifted off now: no tire force
    const tire::TireForces f = tire::tire_forces(t, ch, kin, slip, state_.tire_deflection_m[k]);
    out.force_x_n = f.long_force_n;
    out.force_y_n = f.lat_force_n;
  }
  if (rigid_[k / 2]) {  // the axle's spring on this side, its travel, heave and roll
    const Eigen::Index h = 6 + 2 * (i / 2);
    out.suspension_n = axle_suspension_forces(i / 2, y, z).spring_n[k % 2];
    out.rigid_axle = true;
    out.axle_heave_m = y(h);
    out.axle_roll_rad = y(h + 1);
    out.hub_travel_m = rigid_hub_travel_m(a, i % 2, y(h), y(h + 1));
    return out;
  }
  // Suspension: preloaded spring, bump/rebound damper, stops, anti-roll bar (wheel rates).
  const double s = y(6 + i), sd = z(6 + i), s_other = y(6 + (i ^ 1));
  const double spring =
      shares_[k / 2].group < 0 ? a.spring_stiffness_npm * s : shared_spring_n(i, y);
  double fs = preload_[k] + spring + (sd > 0 ? a.damper_bump_nspm : a.damper_rebound_nspm) * sd;
  if (s > a.bump_stop_travel_m) fs += a.stop_stiffness_npm * (s - a.bump_stop_travel_m);
  if (s < -a.rebound_stop_travel_m) fs += a.stop_stiffness_npm * (s + a.rebound_stop_travel_m);
  fs += a.anti_roll_stiffness_npm * (s - s_other);
  out.suspension_n = fs;
  return out;
}

void VehicleFramework::applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept {
  const Mat3 rot = body_to_road(y(3), y(4), y(5));
  const Vec3 v = z.segment<3>(0), w = z.segment<3>(3);
  const Vec3 g = rot.transpose() * road_.gravity_mps2();
  const double mc = p_.chassis.mass_kg;
  q.setZero(n_);
  contacts_.open(y, z, true);  // the partials' contacts if at the same (y, z)
  // chassis: gravity, velocity-dependent acceleration a_0 = w x v, gyroscopic (explicit terms)
  Vec3 ft = mc * (g - w.cross(v));
  ft.x() -= 0.5 * p_.chassis.air_density_kgpm3 * p_.chassis.drag_area_m2 * v.x() * std::abs(v.x());
  Vec3 tr = -w.cross(inertia_ * w);
  std::array<AxleHousingLoad, kMaxAxles> housing{};  // rigid axles: what their housings take
  for (int i = 0; i < wheel_count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (rigid_[k / 2]) {
      rigid_wheel_applied(i, rot, y, z, g, ft, tr, q, housing[k / 2]);
      continue;
    }
    if (twisted(i)) {
      rear_wheel_applied(i, rot, y, z, g, ft, tr, q);
      continue;
    }
    const double sd = z(6 + i);
    const Vec3 r = wheel_centre(i, y(6 + i));
    const Vec3 es = hub_axis(i);
    const Vec3 a0 = w.cross(v) + w.cross(w.cross(r)) + 2.0 * w.cross(es * sd);
    const CarrierLoad l = carrier_load(i, rot, y, z, g, r, a0);
    const Vec3& f = l.force_n;
    const Vec3& s = l.contact.spin_axis;
    ft += f;
    // the contact force's moment except its spin-axis part (the spin DOF carries it), the
    // drive and brake torques' reactions
    tr += r.cross(f) + l.contact_moment_nm - l.contact_moment_nm.dot(s) * s - l.spin_torque_nm * s;
    q(6 + i) = es.dot(f) - l.tire.suspension_n;  // J_v hub column e_s
  }
  if (any_rigid_) {
    for (int a = 0; a < wheel_count_ / 2; ++a) {  // groups of axles (leaf balance) first
      const Eigen::Index h = 6 + 2 * static_cast<Eigen::Index>(a);
      if (rigid_[static_cast<std::size_t>(a)])
        suspension_[static_cast<std::size_t>(a)]->prepare(y(h), y(h + 1),
                                                          housing[static_cast<std::size_t>(a)]);
    }
    for (int a = 0; a < wheel_count_ / 2; ++a) {
      if (rigid_[static_cast<std::size_t>(a)])
        q.segment<2>(6 + 2 * a) +=
            axle_suspension_forces(a, y, z, housing[static_cast<std::size_t>(a)]).q;
    }
  }
  if (twist_ >= 0) frame_applied(y, z, g, ft, tr, q);
  q.segment<3>(0) = ft;
  q.segment<3>(3) = tr;
  if (free_bodies_) free_bodies_->add_chassis_load(rigid_pose(y, z), q.head<6>());
  contacts_.close();
}

VehicleFramework::CarrierLoad VehicleFramework::carrier_load(int i, const Mat3& rot,
                                                             const Vector& y, const Vector& z,
                                                             const Vec3& g, const Vec3& r,
                                                             const Vec3& a0) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  const Vec3 fw = p_.axles[k / 2].unsprung_mass_kg * (g - a0);
  CarrierLoad l{
      .force_n = fw,
      .contact_moment_nm = Vec3::Zero(),
      .contact = evaluation_contact(rot, y, z, i),
      .tire = {},
      .spin_torque_nm = work_.wheels[k].shaft_torque_nm + work_.wheels[k].brake_torque_nm};
  l.tire = wheel_forces(l.contact, y, z, i);
  const WheelContact& c = l.contact;
  // the tire force acts at the wheel centre; its moment about the centre
  l.force_n = fw + l.tire.force_x_n * c.ex + l.tire.force_y_n * c.ey + l.tire.load_n * c.normal;
  l.contact_moment_nm = (c.lever_m - r).cross(l.force_n - fw);
  return l;
}

void VehicleFramework::suspension_jacobians(int i, const Vector& y, const Vector& z, Matrix& dq_dy,
                                            Matrix& dq_dz) const noexcept {
  // suspension on the hub coordinates (relative DOF: acts on q_h only)
  const AxleParams& ax = p_.axles[static_cast<std::size_t>(i / 2)];
  const Eigen::Index h = 6 + i;
  const double s = y(h);
  const AxleShare& sh = shares_[static_cast<std::size_t>(i / 2)];
  // in a load-sharing group the diagonal w_i^2 k_g; the other axles' terms w_i w_j k_g couple
  // leaves of the arrowhead and stay lagged (soft: the group's heave rate is the springs')
  double stiff =
      (sh.group < 0 ? ax.spring_stiffness_npm : sh.weight * sh.weight * sh.group_rate_npm) +
      ax.anti_roll_stiffness_npm;
  if (s > ax.bump_stop_travel_m || s < -ax.rebound_stop_travel_m) stiff += ax.stop_stiffness_npm;
  dq_dy(h, h) -= stiff;
  dq_dy(h, 6 + (i ^ 1)) += ax.anti_roll_stiffness_npm;
  dq_dz(h, h) -= z(h) > 0 ? ax.damper_bump_nspm : ax.damper_rebound_nspm;
}

void VehicleFramework::tire_jacobians(int i, const Mat3& rot, const Mat3& e_inv, const Vector& y,
                                      const Vector& z, Matrix& dq_dy,
                                      Matrix& dq_dz) const noexcept {
  // tire: force rows at the wheel centre (J_C^T u), velocity rows at the contact (u^T J_P)
  const auto k = static_cast<std::size_t>(i);
  const tire::TmeasyParams& t = p_.axles[k / 2].tire.tmeasy;
  const Eigen::Index h = 6 + i;
  const WheelContact c = evaluation_contact(rot, y, z, i);
  if (c.penetration_m <= 0) return;
  const Vec3 centre = wheel_centre(i, y(h));
  const Vec3 es = hub_axis(i);
  // the rows have non-zeros only in the body columns 0..5 and the hub column h: a 7 x 7
  // sub-block instead of a dense outer product
  TirePartials<1> j;
  tire_partials<1>(c, centre, {&es}, rot, e_inv, t.vertical_stiffness_npm,
                   tire_damping_nspm(t, work_.wheels[k].tire.characteristic, tire_kinematics(c, i)),
                   j);
  scatter_tire_block<1>(j.dq_dz, {h}, dq_dz);
  scatter_tire_block<1>(j.dq_dy, {h}, dq_dy);
}

bool VehicleFramework::force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                                       Matrix& dq_dz) const noexcept {
  dq_dy.setZero(n_, n_);
  dq_dz.setZero(n_, n_);
  contacts_.open(y, z, false);  // kept for the applied forces at the same (y, z)
  const Mat3 rot = body_to_road(y(3), y(4), y(5));
  const Mat3 e_inv = body_rates_from_euler_rates(y(4), y(5));  // K_BB angle part
  for (int i = 0; i < wheel_count_; ++i) {
    if (rigid_[static_cast<std::size_t>(i / 2)]) {
      if (i % 2 == 0) rigid_suspension_jacobians(i / 2, y, z, dq_dy, dq_dz);
      rigid_tire_jacobians(i, rot, e_inv, y, z, dq_dy, dq_dz);
      continue;
    }
    suspension_jacobians(i, y, z, dq_dy, dq_dz);
    if (twisted(i)) {
      rear_tire_jacobians(i, rot, e_inv, y, z, dq_dy, dq_dz);
      continue;
    }
    tire_jacobians(i, rot, e_inv, y, z, dq_dy, dq_dz);
  }
  if (twist_ >= 0) frame_jacobians(dq_dy, dq_dz);
  if (free_bodies_) free_body_jacobians(y, z, rot, e_inv, dq_dy, dq_dz);
  return true;
}

void VehicleFramework::free_body_jacobians(const Vector& y, const Vector& z, const Mat3& rot,
                                           const Mat3& e, Matrix& dq_dy,
                                           Matrix& dq_dz) const noexcept {
  Mat6 ds = Mat6::Zero(), dz = Mat6::Zero();
  free_bodies_->add_chassis_jacobians(rigid_pose(y, z), ds, dz);
  // speed-space displacements -> coordinates: dq/dy = dq/ds K, K = diag(R^T, E) (fixed-size
  // products first: a block of the dynamic matrix would take Eigen's general product)
  Mat6 dy;
  dy.leftCols<3>().noalias() = ds.leftCols<3>() * rot.transpose();
  dy.rightCols<3>().noalias() = ds.rightCols<3>() * e;
  dq_dy.topLeftCorner<6, 6>() += dy;
  dq_dz.topLeftCorner<6, 6>() += dz;
}

tire::TireKinematics VehicleFramework::tire_kinematics(const WheelContact& c,
                                                       int i) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  return {
      c.vx_mps, c.vy_mps, state_.spin_radps[k],
      tire::dynamic_rolling_radius(p_.axles[k / 2].tire.tmeasy.radius_unloaded_m, c.penetration_m)};
}

double VehicleFramework::shared_spring_n(int i, const Vector& y) const noexcept {
  const AxleShare& sh = shares_[static_cast<std::size_t>(i / 2)];
  double travel = 0;  // the group's weighted travel on this side
  for (int j = sh.first_axle; j < sh.first_axle + sh.axle_count; ++j)
    travel += shares_[static_cast<std::size_t>(j)].weight * y(6 + 2 * j + i % 2);
  return sh.weight * sh.group_rate_npm * travel;
}

}  // namespace rig::model::vehicle
