#pragma once
/// @file
/// The framework (eq. 1): chassis (6 DOF) + one hub-travel DOF per wheel.
///   y_V = [x, y, z, yaw, pitch, roll, s_1..s_n],  z_V = [v_body, omega_body, s_1'..s_n'].
/// Mass matrix and generalized forces by Jourdain's principle (method.md sec. 6): the chassis
/// plus each unsprung mass at its wheel centre with J_v = [I, -[r]x, e_s], e_s = d r/d s the
/// tangent of the kinematic tables of eq. (29) (e_z when the hub moves along body z). Suspension
/// forces act on the hub coordinates only; tire forces at the contact points with J_P. K_V =
/// diag(K_BB, I) with K_BB inverted analytically. Speeds are ordered body first, then axle by axle,
/// so that M_VI has the zero blocks of eqs. (30-31) (ArrowheadFactorization). A rigid axle
/// (rigid_axle.h) takes its two slots as heave and roll of the axle body: the same 2 x 2 leaf.
/// With [frame] (frame/frame_torsion.h) one more coordinate, stored last: the frame's twist, in
/// the body's corner of the arrowhead (ArrowheadPartition::body_tail_size).

#include <array>

#include "model/road/road.h"
#include "model/solver/mechanical_block.h"
#include "model/vehicle/evaluation_contacts.h"
#include "model/vehicle/frame/frame_torsion.h"
#include "model/vehicle/load_sharing.h"
#include "model/vehicle/rigid_axle.h"
#include "model/vehicle/vehicle_state.h"
#include "model/vehicle/vehicle_workspace.h"
#include "model/vehicle/wheel_contact.h"

namespace rig::model::vehicle {

class FreeBodies;

class VehicleFramework final : public solver::MechanicalBlock<Eigen::Dynamic> {
 public:
  /// Reads the wheels' spins and tire deflections from `state` and their pose, tire contact and
  /// torques from `work`; its coordinates and speeds are state.framework_y, framework_z.
  VehicleFramework(const VehicleParams& p, VehicleState& state, const VehicleWorkspace& work);
  [[nodiscard]] Eigen::Index size() const noexcept override { return n_; }
  [[nodiscard]] Vector& coordinates() noexcept override { return state_.framework_y; }
  [[nodiscard]] Vector& speeds() noexcept override { return state_.framework_z; }
  void kinematics_inverse(const Vector& y, Matrix& k_inv) const noexcept override;
  /// K^-1 = diag(R, E, I): the rotation and Euler-rate blocks, then the identity.
  [[nodiscard]] Eigen::Index kinematics_block3_size() const noexcept override { return 6; }
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  /// The stiff parts only (method.md sec. 6): suspension springs, dampers, stops and anti-roll
  /// bars on the hub coordinates; tire vertical stiffness and damping; the tire's longitudinal
  /// and lateral damping paths (eq. 24, at fixed f). Each is a scalar times a product of
  /// Jacobian rows (J_C^T u)(u^T J_P). Gravity, gyroscopic and aerodynamic terms stay explicit.
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;

  /// Forces of wheel i at state (y, z) with the newest tire, wheel and steering states.
  [[nodiscard]] WheelForces wheel_forces(const Vector& y, const Vector& z, int i) const noexcept;
  [[nodiscard]] WheelForces wheel_forces(const Mat3& rot, const Vector& y, const Vector& z,
                                         int i) const noexcept;
  /// The same at the wheel's contact c (contact(rot, y, z, i)).
  [[nodiscard]] WheelForces wheel_forces(const WheelContact& c, const Vector& y, const Vector& z,
                                         int i) const noexcept;
  /// The local road plane of wheel i (TMeasy's four probes, local_road_plane.h) around its
  /// static contact point `lookahead_s` on from (y, z): the wheel's lowest point as on a level
  /// road, r_0 below the centre in the wheel plane, moved with the centre's velocity; fore and
  /// aft along the wheel's horizontal heading. A function of (y, z) alone. Only for a road that
  /// is not the plane (road::Road::is_plane).
  [[nodiscard]] LocalRoadPlane road_plane(const Mat3& rot, const Vector& y, const Vector& z, int i,
                                          double lookahead_s, ProbeHints& hints) const noexcept;
  /// Contact kinematics of wheel i at (y, z): on the plane road from the road, else on the
  /// wheel's local road plane of the step (work.wheels[i].road).
  [[nodiscard]] WheelContact contact(const Vector& y, const Vector& z, int i) const noexcept;
  [[nodiscard]] WheelContact contact(const Mat3& rot, const Vector& y, const Vector& z,
                                     int i) const noexcept;
  /// The free bodies whose mounts act on the chassis (model/vehicle/free_body): their
  /// reactions join q and their partials the chassis' corner of the Jacobians. None: null.
  void attach_free_bodies(const FreeBodies* bodies) noexcept { free_bodies_ = bodies; }
  [[nodiscard]] int wheel_count() const noexcept { return wheel_count_; }
  [[nodiscard]] int axle_of(int wheel) const noexcept {
    return axle_of_[static_cast<std::size_t>(wheel)];
  }
  [[nodiscard]] const Vec3& mount(int wheel) const noexcept {
    return mount_[static_cast<std::size_t>(wheel)];
  }
  /// Total mass (sprung + unsprung).
  [[nodiscard]] double total_mass_kg() const noexcept { return total_mass_kg_; }
  /// Static spring preload of wheel i (design height at zero hub travel).
  [[nodiscard]] double preload_n(int i) const noexcept {
    return preload_[static_cast<std::size_t>(i)];
  }
  /// Static vertical force of the support (ChassisParams::supported) on this unit [N, up].
  [[nodiscard]] double support_load_n() const noexcept { return support_load_n_; }
  /// The road under the wheels (gravity in the road frame, height, normal, friction).
  [[nodiscard]] const road::Road& road() const noexcept { return road_; }
  /// Centre of wheel i at hub travel s (body axes, from the CG): the design position plus the
  /// offsets of eq. (29), linear in s about the step's pose (WheelWork, SuspensionKinematics).
  [[nodiscard]] Vec3 wheel_centre(int i, double hub_travel_m) const noexcept;
  /// d(wheel centre)/ds = (dx/dz, dy/dz, 1): the hub-travel column of J_v and J_P.
  [[nodiscard]] Vec3 hub_axis(int i) const noexcept;

  /// Rigid axles (rigid_axle.h): is axle a one, its geometry, and the seam for its suspension
  /// elements (by default springs, dampers, stops and bar: SpringDamperAxleSuspension). The
  /// element must outlive the framework; set before the first step.
  [[nodiscard]] bool rigid(int axle) const noexcept {
    return rigid_[static_cast<std::size_t>(axle)];
  }
  [[nodiscard]] const RigidAxleGeometry& rigid_geometry(int axle) const noexcept {
    return rigid_geometry_[static_cast<std::size_t>(axle)];
  }
  void set_axle_suspension(int axle, const AxleSuspension& element) noexcept {
    suspension_[static_cast<std::size_t>(axle)] = &element;
  }
  /// Frame torsion (frame/frame_torsion.h): the twist's index in y and z (-1: no [frame]), is
  /// axle a behind the split, the frame's geometry, the moment it transmits at (y, z) [N m].
  [[nodiscard]] Eigen::Index twist_index() const noexcept { return twist_; }
  [[nodiscard]] bool on_rear_part(int axle) const noexcept {
    return rear_[static_cast<std::size_t>(axle)];
  }
  [[nodiscard]] const FrameGeometry& frame() const noexcept { return frame_; }
  [[nodiscard]] double torsion_moment_nm(const Vector& y, const Vector& z) const noexcept;
  /// The suspension forces of rigid axle a at (y, z).
  [[nodiscard]] AxleSuspensionForces axle_suspension_forces(int axle, const Vector& y,
                                                            const Vector& z) const noexcept;
  /// The same, the housing's load given (AxleSuspension::forces_under_load): what q takes.
  [[nodiscard]] AxleSuspensionForces axle_suspension_forces(
      int axle, const Vector& y, const Vector& z, const AxleHousingLoad& housing) const noexcept;

 private:
  /// What the tire of wheel i sees at contact c (spin of the state, r_D from the penetration).
  [[nodiscard]] tire::TireKinematics tire_kinematics(const WheelContact& c, int i) const noexcept;
  /// Wheel i's load on its carrier (applied_forces; independent hub or rigid axle).
  struct CarrierLoad {
    Vec3 force_n;            ///< at the wheel centre: weight, inertia, tire force (chassis axes)
    Vec3 contact_moment_nm;  ///< the tire force's moment about the wheel centre
    WheelContact contact;
    WheelForces tire;
    double spin_torque_nm;  ///< drive + brake torque about the spin axis
    /// Adds the load to the body's force and moment sums ft, tr (r: the wheel centre) and
    /// returns its moment on the carrier about the centre: the contact force's except its
    /// spin-axis part (the spin DOF carries that) and the drive and brake torques' reaction.
    Vec3 add_to_body(const Vec3& r, Vec3& ft, Vec3& tr) const noexcept {
      const Vec3& s = contact.spin_axis;
      ft += force_n;
      const Vec3 m_carrier = contact_moment_nm - contact_moment_nm.dot(s) * s - spin_torque_nm * s;
      tr += r.cross(force_n) + m_carrier;
      return m_carrier;
    }
  };
  /// At wheel centre r with the velocity-dependent acceleration a0 (transport, Coriolis: the
  /// hub's or the axle's own) and gravity g (chassis axes).
  [[nodiscard]] CarrierLoad carrier_load(int i, const Mat3& rot, const Vector& y, const Vector& z,
                                         const Vec3& g, const Vec3& r,
                                         const Vec3& a0) const noexcept;
  void suspension_jacobians(int i, const Vector& y, const Vector& z, Matrix& dq_dy,
                            Matrix& dq_dz) const noexcept;
  void tire_jacobians(int i, const Mat3& rot, const Mat3& e_inv, const Vector& y, const Vector& z,
                      Matrix& dq_dy, Matrix& dq_dz) const noexcept;
  // rigid axles (vehicle_framework_rigid.cpp)
  void setup_rigid_axles();
  [[nodiscard]] WheelContact rigid_contact(const Mat3& rot, const Vector& y, const Vector& z,
                                           int i) const noexcept;
  void rigid_mass_matrix(int axle, const Vector& y, Matrix& m) const noexcept;
  /// Wheel i's forces (inertia, gravity, tire, torques) on the body (force, moment about the
  /// CG: added to ft, tr) and on its axle's heave and roll (added to q).
  /// And the housing's fore-aft force and pitch moment (added to `housing`).
  void rigid_wheel_applied(int i, const Mat3& rot, const Vector& y, const Vector& z, const Vec3& g,
                           Vec3& ft, Vec3& tr, Vector& q, AxleHousingLoad& housing) const noexcept;
  void rigid_tire_jacobians(int i, const Mat3& rot, const Mat3& e_inv, const Vector& y,
                            const Vector& z, Matrix& dq_dy, Matrix& dq_dz) const noexcept;
  void rigid_suspension_jacobians(int axle, const Vector& y, const Vector& z, Matrix& dq_dy,
                                  Matrix& dq_dz) const noexcept;

  // frame torsion (vehicle_framework_frame.cpp)
  struct RearWheelPose {
    Vec3 centre_m;    ///< the wheel centre, twisted with the rear part
    Vec3 hub_axis;    ///< Rx(theta) e_s
    Vec3 d_dtwist_m;  ///< e_x x (centre - a)
    Vec3 spin_axis;   ///< Rx(theta) times eq. (29)'s
  };
  void setup_frame();
  [[nodiscard]] RearWheelPose rear_wheel_pose(int i, const Vector& y) const noexcept;
  void frame_mass_matrix(const Vector& y, Matrix& m) const noexcept;
  void rear_wheel_mass_matrix(int i, const Vector& y, Matrix& m) const noexcept;
  [[nodiscard]] WheelContact rear_wheel_contact(const Mat3& rot, const Vector& y, const Vector& z,
                                                int i) const noexcept;
  void rear_wheel_applied(int i, const Mat3& rot, const Vector& y, const Vector& z, const Vec3& g,
                          Vec3& ft, Vec3& tr, Vector& q) const noexcept;
  void frame_applied(const Vector& y, const Vector& z, const Vec3& g, Vec3& ft, Vec3& tr,
                     Vector& q) const noexcept;
  void rear_tire_jacobians(int i, const Mat3& rot, const Mat3& e_inv, const Vector& y,
                           const Vector& z, Matrix& dq_dy, Matrix& dq_dz) const noexcept;
  void frame_jacobians(Matrix& dq_dy, Matrix& dq_dz) const noexcept;
  struct RearRigidPoint {  ///< a rigid axle's wheel behind the split, twisted with the rear part
    Vec3 centre_m, d_dheave, d_droll_m, d_dtwist_m, from_axis_m, spin_axis;
  };
  [[nodiscard]] RearRigidPoint rear_rigid_point(int i, const Vector& y) const noexcept;
  /// Wheel `side` of rigid axle `axle` at y (the roll's sine and cosine through roll_memo_).
  [[nodiscard]] RigidWheelPoint rigid_point(int axle, int side, const Vector& y) const noexcept {
    const Eigen::Index h = 6 + 2 * static_cast<Eigen::Index>(axle);
    return rigid_wheel_point(rigid_geometry_[static_cast<std::size_t>(axle)], side, y(h),
                             roll_memo_[static_cast<std::size_t>(axle)](y(h + 1)));
  }
  [[nodiscard]] TwistRotation twist_rotation(const Vector& y) const noexcept {
    return TwistRotation(twist_memo_(y(twist_)));
  }
  void rear_rigid_mass_matrix(int axle, const Vector& y, Matrix& m) const noexcept;
  [[nodiscard]] WheelContact rear_rigid_contact(const Mat3& rot, const Vector& y, const Vector& z,
                                                int i) const noexcept;
  void rear_rigid_wheel_applied(int i, const Mat3& rot, const Vector& y, const Vector& z,
                                const Vec3& g, Vec3& ft, Vec3& tr, Vector& q,
                                AxleHousingLoad& housing) const noexcept;
  void rear_rigid_tire_jacobians(int i, const Mat3& rot, const Mat3& e_inv, const Vector& y,
                                 const Vector& z, Matrix& dq_dy, Matrix& dq_dz) const noexcept;
  /// Is independent wheel i on the frame's rear part?
  [[nodiscard]] bool twisted(int i) const noexcept {
    return twist_ >= 0 && rear_[static_cast<std::size_t>(i / 2)];
  }

  void free_body_jacobians(const Vector& y, const Vector& z, const Mat3& rot, const Mat3& e,
                           Matrix& dq_dy, Matrix& dq_dz) const noexcept;

  const VehicleParams& p_;
  VehicleState& state_;
  const VehicleWorkspace& work_;
  const FreeBodies* free_bodies_ = nullptr;
  road::Road road_;
  int wheel_count_;
  Eigen::Index n_;
  mutable EvaluationContacts contacts_;  ///< the contacts of force_jacobians for applied_forces
  /// Wheel i's contact in the open force evaluation (evaluation_contacts.h).
  [[nodiscard]] WheelContact evaluation_contact(const Mat3& rot, const Vector& y, const Vector& z,
                                                int i) const noexcept {
    return contacts_.get(i, [&] { return contact(rot, y, z, i); });
  }
  std::array<int, kMaxWheels> axle_of_{};
  std::array<Vec3, kMaxWheels> mount_{};
  std::array<double, kMaxWheels> preload_{};
  std::array<ContactProbes, kMaxWheels> probes_{};  ///< dx = 0.1 r_0, dy = 0.3 B per wheel
  std::array<bool, kMaxAxles> rigid_{};
  AxleShares shares_{};  ///< load-sharing groups (load_sharing.h)
  /// The spring force of wheel i's axle in its load-sharing group: w_i k_g sum_j w_j s_j.
  [[nodiscard]] double shared_spring_n(int i, const Vector& y) const noexcept;
  std::array<RigidAxleGeometry, kMaxAxles> rigid_geometry_{};
  std::array<SpringDamperAxleSuspension, kMaxAxles> default_suspension_{};
  std::array<const AxleSuspension*, kMaxAxles> suspension_{};
  bool any_rigid_ = false;
  FrameGeometry frame_{};
  Eigen::Index twist_ = -1;
  std::array<bool, kMaxAxles> rear_{};
  // the rigid axles' roll and the twist: asked for by every wheel in every evaluation
  mutable std::array<SinCosMemo, kMaxAxles> roll_memo_{};
  mutable SinCosMemo twist_memo_;
  Mat3 inertia_;
  double total_mass_kg_ = 0;
  double support_load_n_ = 0;
};

}  // namespace rig::model::vehicle
