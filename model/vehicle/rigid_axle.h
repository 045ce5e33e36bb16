#pragma once
/// @file
/// A rigid (solid, beam) axle: one body carrying both wheels, with two coordinates against the
/// vehicle body - heave h (its roll centre's travel along body z, up +) and roll phi (about the
/// body's x axis through the roll centre, + left wheel up). They are the axle's two framework
/// coordinates (the slots of the two hub travels of an independent axle), so the axle is one
/// 2 x 2 leaf of the framework's arrowhead M (eqs. 30-31, ArrowheadFactorization).
///
/// Kinematics (exact in phi): a point p0 of the axle (body axes at design height) is at
///   p(h, phi) = c0 + h e_z + Rx(phi) (p0 - c0),  dp/dh = e_z,  dp/dphi = e_x x Rx(phi)(p0 - c0)
/// with c0 the roll centre. The lateral force at a wheel's contact point passes into the body at
/// the roll centre; the wheels' camber is the axle's roll (alpha = phi), their steer gets
/// roll_steer x phi on top of eq. (29)'s gamma. The springs, dampers, stops and anti-roll bar
/// act between the axle and the body (relative coordinates: on h and phi only), behind the
/// AxleSuspension interface (the seam for the five-link leaf spring of sec. 2.3, Fig. 9).

#include <array>

#include <Eigen/Core>

#include "model/vehicle/chassis_kinematics.h"
#include "model/vehicle/sin_cos_memo.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::model::vehicle {

/// Roll-centre heights above the ground from the guidance's geometry (Gillespie, Fundamentals
/// of Vehicle Dynamics, SAE 1992, ch. 7, solid axles):
/// - Panhard rod: where the rod crosses the vehicle's centre line, for a rod across the track the
///   mean of its axle-end and frame-end heights;
/// - four-link: the roll axis runs through the points where the two upper links' and the two
///   lower links' lines meet in plan view; the roll centre is its height at the axle
///   (x forward of the axle, the links' heights there);
/// - leaf: the laterally stiff leaf hands the lateral force to the frame at its eyes: the mean
///   of the front-eye and rear-eye heights (an approximation until the five-link leaf of sec. 2.3
///   gives its own guidance).
[[nodiscard]] inline double panhard_roll_centre_m(double axle_end_height_m,
                                                  double frame_end_height_m) noexcept {
  return 0.5 * (axle_end_height_m + frame_end_height_m);
}
[[nodiscard]] inline double four_link_roll_centre_m(double upper_meet_x_m, double upper_height_m,
                                                    double lower_meet_x_m,
                                                    double lower_height_m) noexcept {
  return upper_height_m + (lower_height_m - upper_height_m) * (0.0 - upper_meet_x_m) /
                              (lower_meet_x_m - upper_meet_x_m);
}
[[nodiscard]] inline double leaf_roll_centre_m(double front_eye_height_m,
                                               double rear_eye_height_m) noexcept {
  return 0.5 * (front_eye_height_m + rear_eye_height_m);
}

/// The axle's geometry in body axes (from the sprung CG) at design height.
struct RigidAxleGeometry {
  Vec3 roll_centre_m = Vec3::Zero();          ///< c0
  std::array<Vec3, 2> wheel_from_centre_m{};  ///< wheel centre - c0, left then right
  double half_track_m = 0;                    ///< the wheels' track / 2
  double extra_roll_inertia_kgm2 =
      0;  ///< roll inertia beyond the wheels' point masses (may be < 0)
};

/// The geometry of axle `a` from its parameters and its wheels' design centres (the framework's
/// mounts, left then right), the roll centre at its height above the ground.
[[nodiscard]] RigidAxleGeometry rigid_axle_geometry(const AxleParams& a, double cg_height_m,
                                                    const Vec3& left_centre_m,
                                                    const Vec3& right_centre_m) noexcept;

/// A wheel of the axle at heave and roll (given by its sine and cosine): its centre,
/// d centre/d roll, and the centre's offset from the (moved) roll centre.
struct RigidWheelPoint {
  Vec3 centre_m;
  Vec3 d_droll_m;    ///< e_x x Rx(phi)(p0 - c0)
  Vec3 from_axis_m;  ///< Rx(phi)(p0 - c0)
};
[[nodiscard]] RigidWheelPoint rigid_wheel_point(const RigidAxleGeometry& g, int side,
                                                double heave_m, const SinCos& roll) noexcept;

/// The hub travel reported for a wheel of a rigid axle: heave +- (track/2) roll (the wheel
/// centre's travel against the body, linear in roll), side 0 left, 1 right.
[[nodiscard]] inline double rigid_hub_travel_m(const AxleParams& a, int side, double heave_m,
                                               double roll_rad) noexcept {
  return heave_m + (side == 0 ? 0.5 : -0.5) * a.track_m * roll_rad;
}

/// What the suspension elements between a rigid axle and the body give: the generalized forces
/// on (heave, roll) [N, N m] and their partials; and the two springs' forces for the report.
struct AxleSuspensionForces {
  Eigen::Vector2d q = Eigen::Vector2d::Zero();
  Eigen::Matrix2d dq_dy = Eigen::Matrix2d::Zero();  ///< d q / d(heave, roll)
  Eigen::Matrix2d dq_dz = Eigen::Matrix2d::Zero();  ///< d q / d(heave', roll')
  std::array<double, 2> spring_n{};                 ///< left, right; compression +
};

/// What the axle housing takes from its wheels beyond heave and roll, body axes at the axle
/// centre (the wheel centres' line): the fore-aft force (tires, the wheels' gravity and
/// inertia) and the pitch moment about +y (the brake torques, whose calipers sit on the housing,
/// and the drive torque's reaction on a live axle).
struct AxleHousingLoad {
  double force_x_n = 0;
  double moment_y_nm = 0;
};

/// The seam for the suspension elements of a rigid axle (springs, dampers, stops, bar today; the
/// five-link leaf spring of sec. 2.3 as a generalized force element tomorrow): everything that
/// acts between the axle and the body, as generalized forces on the axle's coordinates. Called
/// in the RT path: no allocation. Internal forces of a relative coordinate: they act on (heave,
/// roll) only, the body takes their reactions through the Jourdain projection.
class AxleSuspension {
 public:
  AxleSuspension() = default;
  AxleSuspension(const AxleSuspension&) = default;
  AxleSuspension& operator=(const AxleSuspension&) = default;
  AxleSuspension(AxleSuspension&&) = default;
  AxleSuspension& operator=(AxleSuspension&&) = default;
  virtual ~AxleSuspension() = default;
  virtual void forces(double heave_m, double roll_rad, double heave_rate_mps,
                      double roll_rate_radps, AxleSuspensionForces& out) const noexcept = 0;
  /// The same, told what the axle housing takes beyond heave and roll (its fore-aft force and
  /// pitch moment, which the framework passes to the body): elements that guide the axle
  /// fore-aft and in pitch (the leaf spring) find their deflection from it. Called once per
  /// applied-forces evaluation; the default ignores the load.
  virtual void forces_under_load(double heave_m, double roll_rad, double heave_rate_mps,
                                 double roll_rate_radps, const AxleHousingLoad& load,
                                 AxleSuspensionForces& out) const noexcept {
    (void)load;
    forces(heave_m, roll_rad, heave_rate_mps, roll_rate_radps, out);
  }
  /// Told every rigid axle's (heave, roll) and housing load, in axle order, before any
  /// forces_under_load of the same evaluation: elements coupling axles (the leaf balance,
  /// leaf_balance.h) balance their group here. The default does nothing.
  virtual void prepare(double heave_m, double roll_rad,
                       const AxleHousingLoad& load) const noexcept {
    (void)heave_m;
    (void)roll_rad;
    (void)load;
  }
};

/// Two preloaded springs at +-spring_track/2 (wheel-rate keys of the axle: spring_stiffness_npm
/// per spring, bump and rebound stops on each spring's travel), two dampers at
/// +-damper_track/2 (bump and rebound rates), the anti-roll bar on the roll. Each spring's
/// travel is heave +- (spring_track/2) roll, so the roll stiffness is
/// 2 k (spring_track/2)^2 + bar.
class SpringDamperAxleSuspension final : public AxleSuspension {
 public:
  SpringDamperAxleSuspension() = default;
  SpringDamperAxleSuspension(const AxleParams& a, double preload_left_n, double preload_right_n);
  void forces(double heave_m, double roll_rad, double heave_rate_mps, double roll_rate_radps,
              AxleSuspensionForces& out) const noexcept override;

 private:
  double stiffness_npm_ = 0, stop_stiffness_npm_ = 0;
  double bump_stop_m_ = 0, rebound_stop_m_ = 0;
  double damper_bump_nspm_ = 0, damper_rebound_nspm_ = 0;
  double spring_half_track_m_ = 0, damper_half_track_m_ = 0;
  double bar_nmprad_ = 0;
  std::array<double, 2> preload_n_{};
};

}  // namespace rig::model::vehicle
