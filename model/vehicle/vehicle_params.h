#pragma once
/// @file
/// Constant parameters of the generic vehicle (method.md sec. 2 and 6). Plain data, SI units;
/// filled by io/config from TOML. No behaviour here.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "model/kinematics/kinematic_table.h"
#include "model/road/road.h"
#include "model/tire/tmeasy_params.h"
#include "model/vehicle/differential/differential_params.h"
#include "model/vehicle/frame/frame_params.h"
#include "model/vehicle/free_body/free_body_params.h"
#include "model/vehicle/leaf_spring/leaf_spring_params.h"

namespace rig::model::vehicle {

/// A wheel's tire: the TMeasy parameters of model/tire (the curves at F_zN and 2 F_zN, the
/// deflection dynamics of eqs. 22-24, the vertical tire, rolling resistance, v_N), plus the spin
/// inertia of wheel, tire and brake disc.
struct TireParams {
  tire::TmeasyParams tmeasy{};
  double spin_inertia_kgm2 = 1.0;  ///< about the spin axis
};

/// Suspension kinematics of eq. (29) of an axle's LEFT wheel: wheel-centre x, y (offsets from the
/// design position, body axes), alpha (rotation about x: camber), beta (about y) and gamma
/// (about z: toe + steer) as functions of hub travel z and rack travel u at the wheel (after the
/// tie-rod compliance). The right wheel is the mirror image: x_R(z, u) = x_L(z, -u),
/// y_R = -y_L(z, -u), alpha_R = -alpha_L(z, -u), beta_R = beta_L(z, -u), gamma_R = -gamma_L(z, -u).
/// Given as five tables on one grid (u grid symmetric about 0, or a single u line), or generated
/// from the simple geometry below (model/kinematics generate_wheel_kinematics; on a steered axle
/// the steer is asin(u / steering arm)). All zero: the hub moves along body z, no camber or toe.
struct AxleKinematicsParams {
  double x_per_travel = 0;             ///< dx/dz: wheel recession with travel [-]
  double track_per_travel = 0;         ///< dy/dz: half-track change, outwards + [-]
  double track_per_travel2_per_m = 0;  ///< d2y/dz2 / 2: swing-arm arc [1/m]
  double camber_rad = 0;               ///< static alpha of the left wheel
  double camber_per_travel_radpm = 0;  ///< dalpha/dz [rad/m]
  double toe_rad = 0;                  ///< static gamma of the left wheel (+: front to the left)
  double bump_steer_radpm = 0;         ///< dgamma/dz [rad/m]
  /// Generated steer tables: Ackermann share [%]. 100: the inner wheel steers more so that both
  /// wheels' axes meet on the line of the unsteered axles (cot(outer) - cot(inner) = track /
  /// wheelbase); 0: both wheels asin(u / arm), the right the mirror of the left.
  double ackermann_percent = 0;
  /// Given tables of the left wheel, z-major (values[k * u_count + l]); empty: generated.
  kinematics::Grid2D grid{};
  std::vector<double> x_m, y_m, alpha_rad, beta_rad, gamma_rad;
  bool bicubic = true;  ///< Catmull-Rom bicubic (C1) or bilinear interpolation
};

/// How an axle's two wheels move against the body: each on its own hub travel (independent
/// suspension, eq. 29) or together on one rigid axle body (rigid_axle.h).
enum class AxleKind : std::uint8_t { kIndependent, kRigid };
/// What guides a rigid axle laterally, and so sets its roll centre (rigid_axle.h).
enum class AxleGuidance : std::uint8_t { kPanhard, kFourLink, kLeaf };

/// A rigid (solid, beam) axle: one body carrying both wheels, with heave and roll against the
/// body (model/vehicle/rigid_axle.h). `[axle.rigid]` of a `[[axle]] kind = "rigid"`.
struct RigidAxleParams {
  double mass_kg = 700;                   ///< the axle with its wheels, hubs and brakes
  double roll_inertia_kgm2 = 300;         ///< about its centre, longitudinal axis
  double spring_track_m = 1.0;            ///< lateral spacing of the two springs (and stops)
  double damper_track_m = 1.0;            ///< lateral spacing of the two dampers
  double anti_roll_stiffness_nmprad = 0;  ///< the bar, on the axle's roll against the body
  /// Roll steer: the axle's steer (gamma of both wheels, + front to the left) per axle roll
  /// against the body (+ left wheel up) [rad/rad].
  double roll_steer = 0;
  AxleGuidance guidance = AxleGuidance::kPanhard;
  /// The roll centre above the ground at design height, derived from the guidance's geometry
  /// by io/config (rigid_axle.h: roll_centre_height_m); the axle rolls about it.
  double roll_centre_height_m = 0.5;
};

/// One axle: two wheels at +-track/2, hub travel guided by the kinematics of eq. (29).
struct AxleParams {
  AxleKind kind = AxleKind::kIndependent;
  RigidAxleParams rigid{};  ///< kind == kRigid only
  /// A rigid axle on five-link leaf springs (`[axle.leaf_spring]`, leaf_axle.h): one leaf each
  /// side at +-rigid.spring_track_m / 2 instead of the springs (spring_stiffness_npm then only
  /// weighs the axles in the static loads of more than two axles).
  bool has_leaf_spring = false;
  leaf_spring::LeafSpringParams leaf_spring{};
  double position_x_m = 0;  ///< wheel centre x relative to the sprung-mass CG (forward +)
  double track_m = 1.55;
  double unsprung_mass_kg = 40;         ///< per wheel
  double spring_stiffness_npm = 3e4;    ///< at the wheel (wheel rate), per wheel
  double damper_bump_nspm = 3e3;        ///< damping at the wheel, compression
  double damper_rebound_nspm = 5e3;     ///< damping at the wheel, extension
  double bump_stop_travel_m = 0.08;     ///< hub travel where the bump stop engages (up +)
  double rebound_stop_travel_m = 0.10;  ///< magnitude of down travel where the rebound stop engages
  double stop_stiffness_npm = 5e5;
  double anti_roll_stiffness_npm = 1e4;  ///< at the wheels: F = k (s_left - s_right)
  bool steered = false;
  bool driven = false;
  int brake_circuit = 0;               ///< 0 = front circuit, 1 = rear circuit
  double brake_gain_nm_per_pa = 1e-4;  ///< brake torque capacity per wheel per pressure
  /// Steered axle: the kingpin axis meets the ground this far ahead of the contact centre. The
  /// aligning torque is -(n(s_y) + caster trail) F_y, n the tire's pneumatic trail (model/tire).
  double caster_trail_m = 0;
  /// Steered axle: the steering axis' tilt (model/vehicle/steering/README.md "steering axis").
  /// Caster angle: its top tilted rearwards; kingpin inclination: its top tilted inwards; scrub
  /// radius: the contact centre outboard of the axis' ground point (positive scrub). With them
  /// the vertical load gives the jacking torque and F_x its moments (steering_axis.h).
  double caster_angle_rad = 0;
  double kingpin_inclination_rad = 0;
  double scrub_radius_m = 0;
  /// The wheel centre's lateral offset from the axis (kingpin offset at wheel centre), derived
  /// from the above: (r_s + r_0 tan(KPI)) cos(KPI) (Reimpell, The Automotive Chassis, ch. 3);
  /// the vehicle file's spindle_offset_m, if given, must agree with it.
  double spindle_offset_m = 0;
  TireParams tire{};
  AxleKinematicsParams kinematics{};
};

/// Which steering model (sec. 2.2, Fig. 7): simple - the wheels' steer follows the rack through
/// quasi-static tie rods (the steering linkage inside the wheels' kinematics); enhanced - the
/// steering system apart, coupled to each steered wheel's knuckle only by the compliant drag
/// links' / tie rods' forces F_S1, F_S2 (model/vehicle/steering/README.md).
enum class SteeringModel : std::uint8_t { kSimple, kEnhanced };
/// What moves the rack: the column (torsion bar, EPS assist, overriding gear), steer-by-wire
/// actuators, or a real rack on a bench (rack-in-the-loop: its measured travel; enhanced only).
enum class SteeringSystemKind : std::uint8_t { kColumn, kSteerByWire, kRackInTheLoop };

/// The built-in EPS's active return: what EPS software adds to the boost curve so that a released
/// wheel comes back to the centre at low speed, where the tires' restoring moments alone do not
/// overcome the rack's dry friction (the sedan at 20 km/h: 60 N of restoring force at 10 % of a
/// 90 deg turn against 150 N of friction; steering/README.md "active return"). A torque at the
/// pinion against the pinion angle theta = u / i_SB:
///   T_r = -(T_max clamp(theta / theta_sat, -1, 1) + d theta') f(v) max(0, 1 - |T_tb| / T_h)
/// scheduled over the vehicle's speed by a trapezoid f(v) and faded out as the driver's torque
/// on the torsion bar T_tb grows. Off (T_max = 0) by default; never with the ECU's assist (the
/// ECU runs its own) or with the ignition off.
struct ActiveReturnParams {
  double torque_max_nm = 0;           ///< T_max at the pinion [N m]; 0: off
  double saturation_angle_rad = 0.3;  ///< theta_sat: the pinion angle of full return torque
  double damping_nmspr = 0;           ///< d on the pinion speed [N m s/rad]
  /// f(v): 0 below [0], rising to 1 at [1], 1 up to [2], falling to 0 at [3] [m/s]
  std::array<double, 4> speed_mps = {1.4, 2.8, 11.1, 22.2};
  double hands_off_nm = 2.0;  ///< T_h: the torsion-bar torque at which it has faded out
};

/// Rack-and-pinion steering (sec. 2.2).
struct SteeringParams {
  SteeringModel model = SteeringModel::kSimple;             ///< [steering] model
  SteeringSystemKind system = SteeringSystemKind::kColumn;  ///< [steering] system
  bool torque_input =
      false;  ///< false: wheel driven by angle (steering robot); true: by hand torque
  double wheel_inertia_kgm2 = 0.04;  ///< steering wheel + upper column
  double column_damping_nmspr = 0.05;
  double robot_stiffness_nmpr = 300;  ///< angle mode: position servo stiffness
  double robot_damping_nmspr = 8;
  double torsion_bar_stiffness_nmpr = 120;
  double torsion_bar_damping_nmspr = 0.3;
  double rack_per_pinion_m_per_rad = 0.0081;  ///< steering box ratio i_SB
  double rack_mass_kg = 2.0;                  ///< rack + pinion + motor reflected
  double rack_friction_n = 150;   ///< rack dry friction (stick-predicted, solver/dry_friction.h)
  double column_friction_nm = 0;  ///< column bearings' dry friction on the wheel angle
  /// Deprecated, ignored: the regularised friction's speed scale (configs still load with it).
  double rack_friction_speed_mps = 0.002;
  double steering_arm_m = 0.13;          ///< wheel steer = rack travel / arm (small angles)
  double tie_rod_stiffness_npm = 1.5e6;  ///< per side, as seen at the rack
  /// Enhanced model: the tie rod's damping, rack to knuckle, per side [N s/m].
  double tie_rod_damping_nspm = 3000;
  /// Enhanced model: knuckle + wheel inertia about the steering axis, per wheel [kg m^2].
  double knuckle_inertia_kgm2 = 1.0;
  double assist_gain = 4.0;  ///< built-in boost curve: T_a = T_max tanh(G T_tb / T_max)
  double assist_max_nm = 12.0;
  ActiveReturnParams active_return{};  ///< the built-in EPS's return function (boost curve only)
  /// The overriding gear's fastest overlay at the pinion (its motor's speed limit). A step
  /// command is followed at this rate: in one step it jolts the rack (h omega > 2, boosted torsion
  /// bar on the rack mass); with the old regularised friction into a two-step cycle, with the
  /// stick-predicted one it settles and sticks (RESULTS.md). The limit stays: it is the motor's.
  double overlay_rate_max_radps = 10.0;
  /// The superposition (planetary) gear's ratio i_ov = overlay motor angle / its angle at the
  /// pinion: pinion angle = steering-wheel-side angle + motor angle / i_ov. The command stays
  /// the overlay at the pinion (steering_overlay_angle_cmd_rad); i_ov scales the motor side
  /// (VehicleState::overlay_motor_rad, the motor's speed = i_ov x the pinion overlay's rate).
  double overlay_ratio = 1.0;
  /// The position-controlled overlay motor as a first-order lag with this -3 dB frequency
  /// (before the rate limit); 0: ideal (the command as the rate limit lets it through).
  double overlay_bandwidth_hz = 0.0;
  // ---- steer-by-wire ([steering] system = "steer_by_wire", steering/README.md) ----
  /// Hand-wheel actuator: the feedback motor's torque limit on the steering wheel.
  double feedback_torque_max_nm = 10.0;
  /// Road-wheel actuator: motor + gear on the rack, rack travel per motor angle, the motor's
  /// (rotor + gear) inertia (reflected on the rack as J / r^2) and its force limit at the rack.
  double rack_actuator_ratio_m_per_rad = 0.0013;
  double rack_actuator_inertia_kgm2 = 2e-4;
  double rack_actuator_force_max_n = 12000.0;
  /// The motor's and screw's viscous friction at the rack, always acting (powered or not): it
  /// damps the free rack against the tires' aligning stiffness (without it a rack free of
  /// commands shimmies at speed: the sedan at 10 m/s with 1500 N s/m) [N s/m].
  double rack_actuator_damping_nspm = 6000.0;
  /// Force command: the motor's force follows it as a first-order lag (current loop).
  double rack_actuator_time_constant_s = 0.005;
  /// Position command: the actuator's PD position servo, designed for this -3 dB frequency of
  /// rack travel / command on the rack + reflected motor mass.
  double rack_actuator_bandwidth_hz = 10.0;
  /// Which assist acts (a routing decision, set by the rig from [routing] assist_torque_nm):
  /// true: the assist_torque_nm input (the ECU's motor torque) while it is valid, the boost
  /// curve while it is not; false: always the built-in boost curve.
  bool assist_from_input = false;
  /// Angle mode: the steering_wheel_angle_cmd_rad input has a source (a routing decision, set
  /// by the rig: the driver or CAN feeds it). Then the robot lets go of the wheel while that
  /// input is not valid (a driver table's `nan` cell: returnability); without a source it holds
  /// the wheel at 0, as always.
  bool angle_from_input = false;
};

/// Engine, torque converter with lock-up, gearbox, open differentials (sec. 2.3).
struct DrivetrainParams {
  std::vector<double> full_load_speed_radps{80, 200, 400, 600, 700};
  std::vector<double> full_load_torque_nm{120, 230, 250, 210, 150};
  double drag_torque_nm = 15;  ///< at zero throttle
  double drag_torque_per_speed_nms = 0.03;
  double engine_inertia_kgm2 = 0.2;
  double idle_speed_radps = 84;       ///< ~800 rpm
  double idle_gain_per_radps = 0.02;  ///< throttle per rad/s below idle
  double max_speed_radps = 680;
  double converter_capacity_nms2 = 0.0047;  ///< T = k w_e (w_e - w_t)
  double lockup_damping_nms = 50;           ///< lock-up clutch, fully engaged
  double lockup_start_radps = 120;          ///< turbine speed where lock-up starts
  double lockup_full_radps = 180;
  /// The lock-up closes only near the converter's coupling point: from this turbine/engine speed
  /// ratio on (fully at lockup_speed_ratio_full). The control of an automatic keeps it open while
  /// the converter slips hard (a full-throttle launch); a clutch closed across 100+ rad/s of slip
  /// would dump the engine's flywheel into the wheels and spin them up.
  /// The lock-up clutch's torque capacity, fully engaged (scaled by the engagement): it slips
  /// beyond it [N m]; 0: the engine's peak full-load torque.
  double lockup_capacity_nm = 0;
  /// The lock-up closes over this time (its pressure ramp); it opens at once, except that a
  /// running shift holds it as it is (else, at h = 5 ms, the engine's lag behind the new gear
  /// in the inertia phase opens it and the engine flares) [s].
  double lockup_engage_time_s = 0.5;
  double lockup_speed_ratio_start = 0.80;
  double lockup_speed_ratio_full = 0.90;
  std::vector<double> gear_ratios{4.2, 2.4, 1.5, 1.0, 0.8, 0.65};
  double reverse_ratio = 3.6;
  double final_drive_ratio = 3.5;
  double efficiency = 0.92;
  /// Gearbox output + propeller shaft + differential, integrated at the carrier speed w_c (wheel
  /// speed, after the final drive): a propeller-shaft-side J counts as J i_final^2 here.
  double transmission_inertia_kgm2 = 0.5;
  double half_shaft_stiffness_nmpr = 8000;  ///< per driven wheel
  double half_shaft_damping_nmspr = 40;
  double upshift_speed_low_radps = 220;   ///< engine speed for an upshift at zero throttle
  double upshift_speed_high_radps = 560;  ///< engine speed for an upshift at full throttle
  double downshift_speed_radps = 130;
  /// An upshift needs the next gear's turbine speed this far above the downshift speed, so that
  /// the shift cannot land at the downshift point (up/down hysteresis of the schedule).
  double upshift_hysteresis_radps = 30;
  double shift_dwell_s = 0.8;  ///< from the start of a shift to the next decision
  /// Clutch-to-clutch shift between forward gears: a torque phase (1/4: the on-coming clutch
  /// takes the torque over) and an inertia phase (3/4: it slips the turbine to the new speed);
  /// 0: the ratio jumps.
  double shift_time_s = 0.4;
  /// `[[drivetrain.differential]]` (model/vehicle/differential/README.md); empty: open
  /// differentials throughout, every driven wheel the same torque (HalfShafts).
  std::vector<differential::DifferentialParams> differentials;
};

/// Sprung mass (chassis) and aerodynamics.
/// At most this many [chassis] body_points_m (vehicle_faults.h checks them every step).
inline constexpr int kMaxBodyPoints = 32;

struct ChassisParams {
  double mass_kg = 1300;                                ///< sprung mass
  std::array<double, 3> inertia_kgm2{450, 1900, 2100};  ///< Ixx, Iyy, Izz about the CG
  double inertia_xz_kgm2 = 0;
  double cg_height_m = 0.55;   ///< design position, above ground
  double drag_area_m2 = 0.65;  ///< c_d A
  double air_density_kgpm3 = 1.2;
  /// Units of a combination (model/combination), for the spring preloads only (the design
  /// position is the static one): a trailing unit is held at design height at its hitch
  /// (x = support_x_m from the CG) by the unit in front; a leading unit carries the static
  /// hitch load payload_n (down) at x = payload_x_m. Defaults: a vehicle on its own.
  bool supported = false;
  double support_x_m = 0;
  double payload_n = 0;
  double payload_x_m = 0;
  /// Points of the body (body axes, from the CG) that must stay above the road, checked after
  /// every step (vehicle_faults.h). Empty: the corners of a box from the axles, the track and
  /// the CG height (default_body_points). At most kMaxBodyPoints.
  std::vector<std::array<double, 3>> body_points_m;
};

/// Limits beyond which a state is a vehicle fault (vehicle_faults.h); the rig sets them from
/// [rig] fault_roll_limit_rad, fault_pitch_limit_rad, fault_speed_limit_mps,
/// fault_rate_limit_radps.
struct FaultLimits {
  double roll_rad = 1.0;   ///< |roll|
  double pitch_rad = 0.6;  ///< |pitch|
  double speed_mps = 100;  ///< CG speed magnitude; a wheel's spin: this / its unloaded radius
  double rate_radps = 10;  ///< angular rate magnitude (body axes)
};

/// A load-sharing bogie (model/vehicle/load_sharing.h): adjacent independent axles whose
/// springs share the load by a fixed split - a walking beam (two axles, the beam pivoted at
/// pivot_x_m) or connected air springs (equal shares) - or a leaf balance (two leaf-sprung
/// rigid axles, a rocker pivoted at pivot_x_m between their leaves: leaf_balance.h).
/// `[[load_sharing]]` of the vehicle file.
enum class LoadSharingKind : std::uint8_t { kAirSprings, kWalkingBeam, kLeafBalance };
struct LoadSharingParams {
  LoadSharingKind kind = LoadSharingKind::kAirSprings;
  int first_axle = 0;  ///< index from 0, front to rear
  int axle_count = 2;
  double pivot_x_m = 0;  ///< walking beam, leaf balance: the pivot (from the CG, forward +)
  /// Leaf balance: torque rods locate the axles, taking their housings' fore-aft force and pitch
  /// moment (brake and drive reactions) to the frame; the leaves carry the vertical load only.
  bool torque_rods = false;
};

struct VehicleParams {
  std::string name;
  ChassisParams chassis{};
  std::vector<AxleParams> axles;                ///< front to rear
  std::vector<LoadSharingParams> load_sharing;  ///< bogies; empty: every axle on its own springs
  SteeringParams steering{};
  DrivetrainParams drivetrain{};
  road::RoadParams road{};
  /// Below this speed (the larger of the contact point's |v_x| and r_D |w|) a wheel's slips are
  /// reported invalid (WheelReport::slip_valid): TMeasy's slip divides by r_D|w| s + v_N (eqs.
  /// 14-15), so at stand-still it reads the creep speed over v_N - tens to thousands - and
  /// means the direction of a tiny motion, not a slip ratio [m/s].
  double slip_mask_speed_mps = 0.5;
  FaultLimits fault_limits{};
  /// Generic free bodies on mounts (`[[free_body]]`, model/vehicle/free_body); none by default.
  std::vector<FreeBodyParams> free_bodies;
  /// Frame torsion (`[frame]`, model/vehicle/frame); not enabled by default.
  FrameParams frame{};
};

}  // namespace rig::model::vehicle
