#include "io/config/vehicle_file.h"

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>
#include "io/config/differential_config.h"
#include "io/config/frame_config.h"
#include "io/config/free_body_config.h"
#include "io/config/leaf_spring_config.h"
#include "model/report.h"
#include "model/vehicle/leaf_axle_state.h"
#include "model/vehicle/leaf_balance_geometry.h"
#include "model/vehicle/rigid_axle.h"

namespace rig::io::config {
namespace {

/// Bounds of the vehicle file's lists (io/config/strict_table.h: every list is bounded).
constexpr std::size_t kMaxCurvePoints = 1000;  ///< full-load curve
constexpr std::size_t kMaxGears = 32;

using model::tire::TmeasyCurve;
using model::vehicle::AxleParams;
using model::vehicle::TireParams;
using model::vehicle::VehicleParams;

constexpr double kBig = 1e12;

TmeasyCurve read_curve(StrictTable t) {
  TmeasyCurve c;
  c.initial_slope_n = t.number_in("initial_slope_n", 1, kBig);
  c.max_force_n = t.number_in("max_force_n", 1, kBig);
  c.max_slip = t.number_in("slip_at_max", 1e-3, 10);
  c.slide_force_n = t.number_in("sliding_force_n", 0, kBig);
  c.slide_slip = t.number_in("slip_at_sliding", 1e-3, 100);
  t.finish();
  if (c.slide_slip <= c.max_slip) throw t.error("slip_at_sliding must exceed slip_at_max");
  if (c.slide_force_n > c.max_force_n) throw t.error("sliding_force_n must not exceed max_force_n");
  // F(s) of eq. (14) starts with its steepest slope: dF0 above the secant F_M / s_M.
  if (!(c.initial_slope_n * c.max_slip > c.max_force_n))
    throw t.error("initial_slope_n",
                  "must exceed max_force_n / slip_at_max (the secant to the "
                  "maximum; the curve starts with its steepest slope)");
  return c;
}

/// The characteristic at 2 F_zN against the one at F_zN: the force levels grow with the load,
/// at most in proportion (the degressive load dependency of eq. 16).
void check_load_dependency(StrictTable& t, const char* nominal_key, const char* double_key,
                           const TmeasyCurve& n, const TmeasyCurve& d) {
  const auto check = [&](double at_nominal, double at_double, const char* key) {
    if (!(at_double > at_nominal && at_double <= 2 * at_nominal))
      throw t.error(double_key, std::string(key) + " must exceed that of [" + nominal_key +
                                    "] and be at most twice it (forces grow with the load, "
                                    "degressively)");
  };
  check(n.max_force_n, d.max_force_n, "max_force_n");
  check(n.slide_force_n, d.slide_force_n, "sliding_force_n");
}

/// The optional pneumatic trail tables (model::tire::TmeasyTrail; absent: its defaults):
/// trail_nominal / trail_double = { trail_over_length, zero_slip, end_slip } at F_zN / 2 F_zN.
void read_trail(StrictTable& t, model::tire::TmeasyTrail& trail) {
  const auto read = [&](const char* key, double& n0, double& sy0, double& syE) {
    auto c = t.optional_table(key);
    if (!c) return;
    n0 = c->number_in("trail_over_length", 0, 1);
    sy0 = c->number_in("zero_slip", 1e-3, 2);
    syE = c->number_in("end_slip", 1e-3, 3);
    if (!(syE > sy0)) throw c->error("end_slip", "end_slip must exceed zero_slip");
    c->finish();
  };
  read("trail_nominal", trail.trail_over_length_nominal, trail.zero_slip_nominal,
       trail.end_slip_nominal);
  read("trail_double", trail.trail_over_length_double, trail.zero_slip_double,
       trail.end_slip_double);
}

TireParams read_tire(StrictTable t) {
  TireParams tire;
  model::tire::TmeasyParams& p = tire.tmeasy;
  p.radius_unloaded_m = t.number_in("radius_unloaded_m", 0.1, 2);
  p.vertical_stiffness_npm = t.number_in("vertical_stiffness_npm", 1e3, 1e8);
  p.vertical_damping_nspm = t.number_in("vertical_damping_nspm", 0, 1e6);
  p.nominal_load_n = t.number_in("nominal_load_n", 10, 1e6);
  p.longitudinal.at_nominal = read_curve(t.table("longitudinal_nominal"));
  p.longitudinal.at_double = read_curve(t.table("longitudinal_double"));
  p.lateral.at_nominal = read_curve(t.table("lateral_nominal"));
  p.lateral.at_double = read_curve(t.table("lateral_double"));
  check_load_dependency(t, "longitudinal_nominal", "longitudinal_double", p.longitudinal.at_nominal,
                        p.longitudinal.at_double);
  check_load_dependency(t, "lateral_nominal", "lateral_double", p.lateral.at_nominal,
                        p.lateral.at_double);
  p.longitudinal_stiffness_npm = t.number_in("longitudinal_stiffness_npm", 1e3, 1e8);
  p.longitudinal_damping_nspm = t.number_in("longitudinal_damping_nspm", 1, 1e6);
  p.lateral_stiffness_npm = t.number_in("lateral_stiffness_npm", 1e3, 1e8);
  p.lateral_damping_nspm = t.number_in("lateral_damping_nspm", 1, 1e6);
  tire.spin_inertia_kgm2 = t.number_in("spin_inertia_kgm2", 1e-3, 1e3);
  p.rolling_resistance = t.number_in("rolling_resistance", 0.01, 0, 0.1);
  p.velocity_floor_mps = t.number_in("velocity_floor_mps", 0.01, 1e-4, 1);
  p.low_speed_damping_ratio = t.number_in("low_speed_damping_ratio", 1.0, 0, 10);
  p.low_speed_damping_speed_mps = t.number_in("low_speed_damping_speed_mps", 1.0, 0.01, 10);
  read_trail(t, p.trail);
  // the bore torque (model/tire/tmeasy_bore.h); its stiffness is needed once it is on
  p.bore.enabled = t.boolean("bore_torque", false);
  p.bore.stiffness_nmprad = p.bore.enabled ? t.number_in("bore_stiffness_nmprad", 1, 1e7)
                                           : t.number_in("bore_stiffness_nmprad", 0, 0, 1e7);
  p.bore.damping_nmsprad = t.number_in("bore_damping_nmsprad", 0, 0, 1e5);
  p.bore.contact_width_m = t.number_in("contact_width_m", 0.2, 0.01, 2);
  t.finish();
  return tire;
}

/// [axle.kinematics]: eq. (29) of the axle's left wheel, as the simple geometry or as five
/// tables on one grid (model::vehicle::AxleKinematicsParams).
model::vehicle::AxleKinematicsParams read_kinematics(StrictTable t) {
  model::vehicle::AxleKinematicsParams k;
  k.x_per_travel = t.number_in("x_per_travel", 0, -2, 2);
  k.track_per_travel = t.number_in("track_per_travel", 0, -2, 2);
  k.track_per_travel2_per_m = t.number_in("track_per_travel2_per_m", 0, -50, 50);
  k.camber_rad = t.number_in("camber_rad", 0, -0.3, 0.3);
  k.camber_per_travel_radpm = t.number_in("camber_per_travel_radpm", 0, -20, 20);
  k.toe_rad = t.number_in("toe_rad", 0, -0.1, 0.1);
  k.bump_steer_radpm = t.number_in("bump_steer_radpm", 0, -5, 5);
  k.ackermann_percent = t.number_in("ackermann_percent", 0, -100, 150);
  k.bicubic = t.choice("interpolation", "bicubic", {"bicubic", "bilinear"}) == "bicubic";
  if (auto g = t.optional_table("grid")) {
    k.grid.z_min = g->number_in("z_min_m", -1, 1);
    k.grid.z_step = g->number_in("z_step_m", 1e-4, 1);
    k.grid.z_count = static_cast<int>(g->integer_in("z_count", 2, 1000));
    k.grid.u_count = static_cast<int>(g->integer_in("u_count", 1, 1, 1000));
    if (k.grid.u_count > 1) {
      k.grid.u_step = g->number_in("u_step_m", 1e-5, 1);
      k.grid.u_min = -0.5 * k.grid.u_step * (k.grid.u_count - 1);  // symmetric about u = 0
    }
    g->finish();
    const auto n =
        static_cast<std::size_t>(k.grid.z_count) * static_cast<std::size_t>(k.grid.u_count);
    const auto table = [&](const char* key) {
      std::vector<double> v = t.numbers(key);
      if (v.size() != n)
        throw t.error(key, std::string(key) + ": need z_count x u_count = " + std::to_string(n) +
                               " values (z-major)");
      return v;
    };
    if (k.ackermann_percent != 0)
      throw t.error("ackermann_percent",
                    "ackermann_percent applies to generated steer tables, not to given ones "
                    "(give each wheel's gamma_rad instead)");
    k.x_m = table("x_m");
    k.y_m = table("y_m");
    k.alpha_rad = table("alpha_rad");
    k.beta_rad = table("beta_rad");
    k.gamma_rad = table("gamma_rad");
  }
  t.finish();
  return k;
}

/// The steering-axis geometry of an axle (AxleParams; model/vehicle/steering/README.md). The
/// spindle offset follows from the other keys; a given spindle_offset_m is checked against it.
void read_steering_axis(StrictTable& t, AxleParams& a) {
  a.caster_angle_rad = t.number_in("caster_angle_rad", 0, -0.3, 0.5);
  a.kingpin_inclination_rad = t.number_in("kingpin_inclination_rad", 0, -0.1, 0.4);
  a.scrub_radius_m = t.number_in("scrub_radius_m", 0, -0.1, 0.1);
  const double r0 = a.tire.tmeasy.radius_unloaded_m;
  a.spindle_offset_m = (a.scrub_radius_m + r0 * std::tan(a.kingpin_inclination_rad)) *
                       std::cos(a.kingpin_inclination_rad);
  if (t.has("spindle_offset_m")) {
    const double given = t.number_in("spindle_offset_m", -0.3, 0.3);
    if (std::abs(given - a.spindle_offset_m) > 0.005)
      throw t.error("spindle_offset_m",
                    "spindle_offset_m = " + std::to_string(given) +
                        " m disagrees with the axis: (scrub_radius_m + r_0 "
                        "tan(kingpin_inclination_rad)) cos(kingpin_inclination_rad) = " +
                        std::to_string(a.spindle_offset_m) +
                        " m (give it within 5 mm or leave "
                        "it out)");
  }
}

/// [axle.rigid] of a `kind = "rigid"` axle (model/vehicle/rigid_axle.h): the axle body, its
/// springs' and dampers' tracks, bar, roll steer and the guidance that sets its roll centre.
void read_rigid_axle(StrictTable t, AxleParams& a) {
  model::vehicle::RigidAxleParams& r = a.rigid;
  r.mass_kg = t.number_in("mass_kg", 2, 10000);
  r.roll_inertia_kgm2 = t.number_in("roll_inertia_kgm2", 0.01, 1e5);
  r.spring_track_m = t.number_in("spring_track_m", 0.1, 4);
  r.damper_track_m = t.number_in("damper_track_m", r.spring_track_m, 0.1, 4);
  r.anti_roll_stiffness_nmprad = t.number_in("anti_roll_stiffness_nmprad", 0, 0, 1e9);
  r.roll_steer = t.number_in("roll_steer", 0, -1, 1);
  const std::string g = t.choice("guidance", "", {"panhard", "four_link", "leaf"});
  const auto height = [&t](std::string_view key) { return t.number_in(key, 0, 3); };
  if (g == "panhard") {
    r.guidance = model::vehicle::AxleGuidance::kPanhard;
    const double axle_end = height("panhard_axle_height_m");
    r.roll_centre_height_m = model::vehicle::panhard_roll_centre_m(
        axle_end, t.number_in("panhard_frame_height_m", axle_end, 0, 3));
  } else if (g == "four_link") {
    r.guidance = model::vehicle::AxleGuidance::kFourLink;
    const double xu = t.number_in("upper_links_meet_x_m", -50, 50);
    const double hu = height("upper_links_height_m");
    const double xl = t.number_in("lower_links_meet_x_m", -50, 50);
    const double hl = height("lower_links_height_m");
    if (std::abs(xl - xu) < 0.05)
      throw t.error("lower_links_meet_x_m",
                    "the upper and lower links must meet at different x (>= 0.05 m apart): the "
                    "roll axis runs through both points");
    r.roll_centre_height_m = model::vehicle::four_link_roll_centre_m(xu, hu, xl, hl);
    if (!(r.roll_centre_height_m >= 0 && r.roll_centre_height_m <= 3))
      throw t.error("lower_links_meet_x_m",
                    "gives a roll centre " + std::to_string(r.roll_centre_height_m) +
                        " m above the ground at the axle; it must lie in [0, 3] m");
  } else {
    r.guidance = model::vehicle::AxleGuidance::kLeaf;
    const double front = height("leaf_front_eye_height_m");
    r.roll_centre_height_m =
        model::vehicle::leaf_roll_centre_m(front, height("leaf_rear_eye_height_m"));
  }
  t.finish();
}

/// [axle.leaf_spring] of a rigid axle (model/vehicle/leaf_axle.h): the leaves are its springs,
/// at [axle.rigid]'s spring_track_m (which the leaf table's must match).
void read_leaf_axle(StrictTable& t, AxleParams& a) {
  const std::optional<LeafSpringConfig> leaf = read_axle_leaf_spring(t);
  if (!leaf) return;
  if (std::abs(leaf->spring_track_m - a.rigid.spring_track_m) > 1e-3)
    throw t.error("leaf_spring",
                  "[axle.leaf_spring] spring_track_m = " + std::to_string(leaf->spring_track_m) +
                      " m differs from [axle.rigid] spring_track_m = " +
                      std::to_string(a.rigid.spring_track_m) +
                      " m (the leaves are the axle's springs)");
  a.has_leaf_spring = true;
  a.leaf_spring = leaf->params;
}

AxleParams read_axle(StrictTable t, const std::map<std::string, TireParams>& tires) {
  AxleParams a;
  a.position_x_m = t.number_in("position_x_m", -20, 20);
  a.track_m = t.number_in("track_m", 0.5, 4);
  const bool rigid = t.choice("kind", "independent", {"independent", "rigid"}) == "rigid";
  if (rigid) {
    // the axle body's mass and bar are [axle.rigid]'s: the per-wheel keys would contradict them
    for (const char* key : {"unsprung_mass_kg", "anti_roll_stiffness_npm"}) {
      if (t.has(key))
        throw t.error(key,
                      "a rigid axle takes its mass and bar from [axle.rigid] (mass_kg, "
                      "anti_roll_stiffness_nmprad)");
    }
    a.kind = model::vehicle::AxleKind::kRigid;
    read_rigid_axle(t.table("rigid"), a);
    a.unsprung_mass_kg = 0.5 * a.rigid.mass_kg;  // each wheel's point mass (rigid_axle.h)
    a.anti_roll_stiffness_npm = 0;
    read_leaf_axle(t, a);
  } else {
    if (t.has("rigid")) throw t.error("rigid", "[axle.rigid] needs kind = \"rigid\"");
    if (t.has("leaf_spring"))
      throw t.error("leaf_spring", "[axle.leaf_spring] needs kind = \"rigid\"");
    a.unsprung_mass_kg = t.number_in("unsprung_mass_kg", 1, 5000);
  }
  a.spring_stiffness_npm = t.number_in("spring_stiffness_npm", 1e2, 1e8);
  a.damper_bump_nspm = t.number_in("damper_bump_nspm", 0, 1e7);
  a.damper_rebound_nspm = t.number_in("damper_rebound_nspm", 0, 1e7);
  a.bump_stop_travel_m = t.number_in("bump_stop_travel_m", 0.001, 1);
  a.rebound_stop_travel_m = t.number_in("rebound_stop_travel_m", 0.001, 1);
  a.stop_stiffness_npm = t.number_in("stop_stiffness_npm", 0, 1e9);
  if (!rigid) a.anti_roll_stiffness_npm = t.number_in("anti_roll_stiffness_npm", 0, 1e8);
  a.steered = t.boolean("steered", false);
  a.driven = t.boolean("driven", false);
  a.brake_circuit = t.choice("brake_circuit", "front", {"front", "rear"}) == "front" ? 0 : 1;
  a.brake_gain_nm_per_pa = t.number_in("brake_gain_nm_per_pa", 0, 1);
  a.caster_trail_m = t.number_in("caster_trail_m", 0, -0.1, 0.3);
  const std::string tire = t.string("tire");
  const auto it = tires.find(tire);
  if (it == tires.end()) throw t.error("tire", "no [tires." + tire + "] table");
  a.tire = it->second;
  if (auto k = t.optional_table("kinematics")) a.kinematics = read_kinematics(*k);
  read_steering_axis(t, a);
  t.finish();
  return a;
}

/// [[load_sharing]] kind = "leaf_balance": two leaf-sprung rigid axles, the rocker's pivot between
/// the front leaf's shackle pin and the rear leaf's front eye (model/vehicle/leaf_balance.h).
void read_leaf_balance(StrictTable& t, const VehicleParams& p,
                       model::vehicle::LoadSharingParams& g) {
  if (g.axle_count != 2) throw t.error("axles", "a leaf balance carries two axles");
  const auto& front = p.axles[static_cast<std::size_t>(g.first_axle)];
  const auto& rear = p.axles[static_cast<std::size_t>(g.first_axle) + 1];
  if (!front.has_leaf_spring || !rear.has_leaf_spring)
    throw t.error("axles",
                  "a leaf balance carries two rigid axles on leaf springs "
                  "([axle.leaf_spring])");
  g.pivot_x_m = t.number_in("pivot_x_m", rear.position_x_m, front.position_x_m);
  g.torque_rods = t.boolean("torque_rods", false);
  try {
    (void)model::vehicle::leaf_balance_geometry(front, rear, g.pivot_x_m);
  } catch (const std::invalid_argument& e) {
    throw t.error("pivot_x_m", e.what());
  }
}

/// [[load_sharing]]: a bogie of adjacent axles sharing its load (model/vehicle/load_sharing.h).
model::vehicle::LoadSharingParams read_load_sharing(StrictTable t, const VehicleParams& p) {
  model::vehicle::LoadSharingParams g;
  const std::string kind = t.choice("kind", "", {"air_springs", "walking_beam", "leaf_balance"});
  g.kind = kind == "walking_beam"   ? model::vehicle::LoadSharingKind::kWalkingBeam
           : kind == "leaf_balance" ? model::vehicle::LoadSharingKind::kLeafBalance
                                    : model::vehicle::LoadSharingKind::kAirSprings;
  const std::vector<long long> axles = t.integers("axles", model::kMaxWheelsPerUnit / 2);
  const auto n = static_cast<long long>(p.axles.size());
  for (std::size_t i = 0; i < axles.size(); ++i) {
    if (axles[i] < 1 || axles[i] > n || (i > 0 && axles[i] != axles[i - 1] + 1))
      throw t.error("axles", "the bogie's axles: adjacent axle numbers from 1 to " +
                                 std::to_string(n) + ", front to rear (e.g. [2, 3, 4])");
  }
  if (axles.size() < 2) throw t.error("axles", "a bogie shares its load among 2 or more axles");
  g.first_axle = static_cast<int>(axles.front() - 1);
  g.axle_count = static_cast<int>(axles.size());
  if (g.kind == model::vehicle::LoadSharingKind::kLeafBalance) {
    read_leaf_balance(t, p, g);
    t.finish();
    return g;
  }
  for (long long a : axles) {
    if (p.axles[static_cast<std::size_t>(a - 1)].kind != model::vehicle::AxleKind::kIndependent)
      throw t.error("axles", "axle " + std::to_string(a) +
                                 " is rigid: load sharing acts on independent axles only");
  }
  if (g.kind == model::vehicle::LoadSharingKind::kWalkingBeam) {
    if (g.axle_count != 2) throw t.error("axles", "a walking beam carries two axles");
    const double x1 = p.axles[static_cast<std::size_t>(g.first_axle)].position_x_m;
    const double x2 = p.axles[static_cast<std::size_t>(g.first_axle) + 1].position_x_m;
    g.pivot_x_m = t.number_in("pivot_x_m", x2 + 0.01, x1 - 0.01);
  }
  t.finish();
  return g;
}

/// The built-in EPS's active return (steering/README.md "active return"); off without its keys.
void read_active_return(StrictTable& t, model::vehicle::ActiveReturnParams& r) {
  r.torque_max_nm = t.number_in("active_return_torque_nm", 0.0, 0, 100);
  r.saturation_angle_rad = t.number_in("active_return_angle_rad", 0.3, 1e-3, 10);
  r.damping_nmspr = t.number_in("active_return_damping_nmspr", 0.0, 0, 100);
  r.hands_off_nm = t.number_in("active_return_hands_off_nm", 2.0, 1e-3, 100);
  if (t.has("active_return_speed_mps")) {
    const std::vector<double> v = t.numbers("active_return_speed_mps", 4);
    if (v.size() != 4 || !(v[0] >= 0 && v[0] <= v[1] && v[1] <= v[2] && v[2] <= v[3]) ||
        !std::isfinite(v[3]))
      throw t.error("active_return_speed_mps",
                    "needs 4 finite speeds [on, full, fade, off] >= 0, not decreasing [m/s]");
    std::copy(v.begin(), v.end(), r.speed_mps.begin());
  }
}

/// Reads [steering]; returns the old `trail_m` if the file gives it (see read_vehicle_file).
std::optional<double> read_steering(StrictTable t, model::vehicle::SteeringParams& s) {
  using model::vehicle::SteeringModel;
  using model::vehicle::SteeringSystemKind;
  s.model = t.choice("model", "simple", {"simple", "enhanced"}) == "enhanced"
                ? SteeringModel::kEnhanced
                : SteeringModel::kSimple;
  const std::string system =
      t.choice("system", "column", {"column", "steer_by_wire", "rack_in_the_loop"});
  s.system = system == "column"          ? SteeringSystemKind::kColumn
             : system == "steer_by_wire" ? SteeringSystemKind::kSteerByWire
                                         : SteeringSystemKind::kRackInTheLoop;
  s.torque_input = t.choice("input", "angle", {"angle", "torque"}) == "torque";
  s.wheel_inertia_kgm2 = t.number_in("wheel_inertia_kgm2", 1e-3, 10);
  s.column_damping_nmspr = t.number_in("column_damping_nmspr", 0, 100);
  s.robot_stiffness_nmpr = t.number_in("robot_stiffness_nmpr", 300, 1, 1e5);
  s.robot_damping_nmspr = t.number_in("robot_damping_nmspr", 8, 0, 1e4);
  s.torsion_bar_stiffness_nmpr = t.number_in("torsion_bar_stiffness_nmpr", 1, 1e5);
  s.torsion_bar_damping_nmspr = t.number_in("torsion_bar_damping_nmspr", 0, 1e3);
  s.rack_per_pinion_m_per_rad = t.number_in("rack_per_pinion_m_per_rad", 1e-4, 1);
  s.rack_mass_kg = t.number_in("rack_mass_kg", 0.1, 1000);
  s.rack_friction_n = t.number_in("rack_friction_n", 0, 1e5);
  // deprecated (the regularised friction's scale), accepted and ignored: friction is
  // stick-predicted now
  s.rack_friction_speed_mps = t.number_in("rack_friction_speed_mps", 0.002, 1e-5, 1);
  s.column_friction_nm = t.number_in("column_friction_nm", 0, 0, 1e3);
  s.steering_arm_m = t.number_in("steering_arm_m", 0.01, 2);
  s.tie_rod_stiffness_npm = t.number_in("tie_rod_stiffness_npm", 1e3, 1e10);
  // the enhanced model's knuckles (model/vehicle/steering/README.md); read for both models
  s.tie_rod_damping_nspm = t.number_in("tie_rod_damping_nspm", 3000, 0, 1e7);
  s.knuckle_inertia_kgm2 = t.number_in("knuckle_inertia_kgm2", 1.0, 1e-3, 100);
  std::optional<double> trail_m;
  if (t.has("trail_m")) trail_m = t.number_in("trail_m", 0, 0.5);
  s.assist_gain = t.number_in("assist_gain", 0, 100);
  s.assist_max_nm = t.number_in("assist_max_nm", 1e-3, 1e4);
  read_active_return(t, s.active_return);
  // the overriding gear (steering/README.md "overriding gear"); defaults: today's simple gear
  s.overlay_ratio = t.number_in("overlay_ratio", 1.0, 1e-3, 1e3);
  s.overlay_bandwidth_hz = t.number_in("overlay_bandwidth_hz", 0.0, 0, 1e3);
  s.overlay_rate_max_radps = t.number_in("overlay_rate_max_radps", 10.0, 1e-3, 1e3);
  if (s.system == SteeringSystemKind::kSteerByWire) {  // steering/README.md "steer-by-wire"
    s.feedback_torque_max_nm = t.number_in("feedback_torque_max_nm", 0, 1e3);
    s.rack_actuator_ratio_m_per_rad = t.number_in("rack_actuator_ratio_m_per_rad", 1e-5, 1);
    s.rack_actuator_inertia_kgm2 = t.number_in("rack_actuator_inertia_kgm2", 0, 1);
    s.rack_actuator_force_max_n = t.number_in("rack_actuator_force_max_n", 0, 1e6);
    s.rack_actuator_damping_nspm = t.number_in("rack_actuator_damping_nspm", 0, 1e6);
    s.rack_actuator_time_constant_s = t.number_in("rack_actuator_time_constant_s", 1e-4, 10);
    s.rack_actuator_bandwidth_hz = t.number_in("rack_actuator_bandwidth_hz", 0.1, 100);
  }
  t.finish();
  return trail_m;
}

/// Engine speeds that the gear selection can use: idle < shift speeds < maximum, and a
/// downshift speed below the upshift speeds (else it shifts back and forth).
void check_shift_speeds(StrictTable& t, const model::vehicle::DrivetrainParams& d) {
  if (!(d.idle_speed_radps < d.max_speed_radps))
    throw t.error("max_speed_radps", "must exceed idle_speed_radps");
  if (!(d.upshift_speed_low_radps <= d.upshift_speed_high_radps))
    throw t.error("upshift_speed_high_radps", "must not be below upshift_speed_low_radps");
  if (!(d.downshift_speed_radps < d.upshift_speed_low_radps))
    throw t.error("downshift_speed_radps", "must be below upshift_speed_low_radps");
  if (!(d.upshift_speed_high_radps <= d.max_speed_radps))
    throw t.error("upshift_speed_high_radps", "must not exceed max_speed_radps");
}

void read_drivetrain(StrictTable t, model::vehicle::DrivetrainParams& d,
                     const std::vector<model::vehicle::AxleParams>& axles) {
  d.full_load_speed_radps = t.numbers("full_load_speed_radps", kMaxCurvePoints);
  d.full_load_torque_nm = t.numbers("full_load_torque_nm", kMaxCurvePoints);
  if (d.full_load_speed_radps.size() < 2 ||
      d.full_load_speed_radps.size() != d.full_load_torque_nm.size()) {
    throw t.error("full_load_torque_nm", "needs as many entries as full_load_speed_radps (>= 2)");
  }
  for (std::size_t i = 0; i < d.full_load_speed_radps.size(); ++i) {
    if (!(d.full_load_speed_radps[i] > (i == 0 ? 0.0 : d.full_load_speed_radps[i - 1])) ||
        !std::isfinite(d.full_load_speed_radps[i])) {
      throw t.error("full_load_speed_radps", "must be finite, > 0 and strictly increasing");
    }
    if (!(d.full_load_torque_nm[i] >= 0 && d.full_load_torque_nm[i] <= 1e5)) {
      throw t.error("full_load_torque_nm", "engine torques must lie in [0, 1e5] N m");
    }
  }
  d.drag_torque_nm = t.number_in("drag_torque_nm", 0, 1e4);
  d.drag_torque_per_speed_nms = t.number_in("drag_torque_per_speed_nms", 0, 100);
  d.engine_inertia_kgm2 = t.number_in("engine_inertia_kgm2", 1e-3, 100);
  d.idle_speed_radps = t.number_in("idle_speed_radps", 10, 500);
  d.idle_gain_per_radps = t.number_in("idle_gain_per_radps", 0, 10);
  d.max_speed_radps = t.number_in("max_speed_radps", 50, 2000);
  d.converter_capacity_nms2 = t.number_in("converter_capacity_nms2", 1e-5, 10);
  d.lockup_damping_nms = t.number_in("lockup_damping_nms", 0, 1e5);
  d.lockup_start_radps = t.number_in("lockup_start_radps", 0, 2000);
  d.lockup_full_radps = t.number_in("lockup_full_radps", 0, 2000);
  if (d.lockup_full_radps <= d.lockup_start_radps)
    throw t.error("lockup_full_radps", "must exceed lockup_start_radps");
  d.lockup_capacity_nm = t.number_in("lockup_capacity_nm", 0.0, 0, 1e6);
  d.lockup_engage_time_s = t.number_in("lockup_engage_time_s", d.lockup_engage_time_s, 0, 10);
  d.lockup_speed_ratio_start =
      t.number_in("lockup_speed_ratio_start", d.lockup_speed_ratio_start, 0, 1);
  d.lockup_speed_ratio_full =
      t.number_in("lockup_speed_ratio_full", d.lockup_speed_ratio_full, 0, 1);
  if (d.lockup_speed_ratio_full <= d.lockup_speed_ratio_start)
    throw t.error("lockup_speed_ratio_full", "must exceed lockup_speed_ratio_start");
  d.gear_ratios = t.numbers("gear_ratios", kMaxGears);
  if (d.gear_ratios.empty()) throw t.error("gear_ratios", "needs at least one gear");
  for (std::size_t i = 0; i < d.gear_ratios.size(); ++i) {
    const double r = d.gear_ratios[i];
    if (!(r >= 0.1 && r <= 50) || (i > 0 && !(r < d.gear_ratios[i - 1])))
      throw t.error("gear_ratios",
                    "ratios must lie in [0.1, 50] and fall strictly from first gear to top gear");
  }
  d.reverse_ratio = t.number_in("reverse_ratio", 0.1, 50);
  d.final_drive_ratio = t.number_in("final_drive_ratio", 0.1, 50);
  d.efficiency = t.number_in("efficiency", 0.1, 1);
  d.transmission_inertia_kgm2 = t.number_in("transmission_inertia_kgm2", 1e-3, 1e3);
  d.half_shaft_stiffness_nmpr = t.number_in("half_shaft_stiffness_nmpr", 10, 1e8);
  d.half_shaft_damping_nmspr = t.number_in("half_shaft_damping_nmspr", 0.1, 1e6);
  d.upshift_speed_low_radps = t.number_in("upshift_speed_low_radps", 10, 2000);
  d.upshift_speed_high_radps = t.number_in("upshift_speed_high_radps", 10, 2000);
  d.downshift_speed_radps = t.number_in("downshift_speed_radps", 10, 2000);
  d.upshift_hysteresis_radps =
      t.number_in("upshift_hysteresis_radps", d.upshift_hysteresis_radps, 0, 1000);
  d.shift_dwell_s = t.number_in("shift_dwell_s", 0, 10);
  d.shift_time_s = t.number_in("shift_time_s", d.shift_time_s, 0, 5);
  check_shift_speeds(t, d);
  if (d.shift_time_s > d.shift_dwell_s)
    throw t.error("shift_time_s", "must not exceed shift_dwell_s (a shift ends before the next)");
  d.differentials = read_differentials(t, axles);
  t.finish();
}

/// [chassis] body_points_m = [[x, y, z], ...]: body axes from the CG (vehicle_faults.h).
std::vector<std::array<double, 3>> read_body_points(StrictTable& c) {
  std::vector<std::array<double, 3>> points;
  for (const auto& row : c.number_rows("body_points_m", 3, model::vehicle::kMaxBodyPoints)) {
    for (const double v : row) {
      if (!std::isfinite(v) || std::abs(v) > 100)
        throw c.error("body_points_m", "coordinates must be finite, within +-100 m");
    }
    points.push_back({row[0], row[1], row[2]});
  }
  if (points.empty() || points.size() > static_cast<std::size_t>(model::vehicle::kMaxBodyPoints))
    throw c.error("body_points_m",
                  "needs 1 to " + std::to_string(model::vehicle::kMaxBodyPoints) + " points");
  return points;
}

/// A rigid body's inertia: each principal moment at most the sum of the other two (triangle
/// inequality), and the x-z block positive definite.
void check_inertia(StrictTable& c, const std::array<double, 3>& i, double ixz) {
  static constexpr std::array<const char*, 3> kKeys{"inertia_xx_kgm2", "inertia_yy_kgm2",
                                                    "inertia_zz_kgm2"};
  for (std::size_t k = 0; k < 3; ++k) {
    if (!(i[k] <= i[(k + 1) % 3] + i[(k + 2) % 3]))
      throw c.error(kKeys[k],
                    "no rigid body has these inertias: each principal moment must be "
                    "at most the sum of the other two");
  }
  if (!(ixz * ixz < i[0] * i[2]))
    throw c.error("inertia_xz_kgm2", "must satisfy xz^2 < xx * zz (positive definite)");
}

/// [[axle]] tables from the front to the rear, each at its own position.
void check_axle_order(std::vector<StrictTable>& tables, const std::vector<AxleParams>& axles) {
  for (std::size_t i = 1; i < axles.size(); ++i) {
    if (!(axles[i].position_x_m < axles[i - 1].position_x_m))
      throw tables[i].error("position_x_m", "must be below that of the axle before (" +
                                                std::to_string(axles[i - 1].position_x_m) +
                                                " m): [[axle]] tables go from front to rear");
  }
}

/// [chassis].
void read_chassis(StrictTable c, model::vehicle::ChassisParams& chassis) {
  chassis.mass_kg = c.number_in("mass_kg", 1, 1e6);
  chassis.inertia_kgm2 = {c.number_in("inertia_xx_kgm2", 1e-3, 1e8),
                          c.number_in("inertia_yy_kgm2", 1e-3, 1e8),
                          c.number_in("inertia_zz_kgm2", 1e-3, 1e8)};
  chassis.inertia_xz_kgm2 = c.number_in("inertia_xz_kgm2", 0, -1e7, 1e7);
  check_inertia(c, chassis.inertia_kgm2, chassis.inertia_xz_kgm2);
  chassis.cg_height_m = c.number_in("cg_height_m", 0.05, 5);
  chassis.drag_area_m2 = c.number_in("drag_area_m2", 0, 50);
  chassis.air_density_kgpm3 = c.number_in("air_density_kgpm3", 1.2, 0, 2);
  if (c.has("body_points_m")) chassis.body_points_m = read_body_points(c);
  c.finish();
}

}  // namespace

/// Every [[load_sharing]] bogie; an axle in two of them is an error.
void read_bogies(StrictTable& t, VehicleParams& p) {
  const std::vector<StrictTable> bogies =
      t.has("load_sharing") ? t.tables("load_sharing", model::kMaxWheelsPerUnit / 4)
                            : std::vector<StrictTable>{};
  for (const StrictTable& g : bogies) {
    p.load_sharing.push_back(read_load_sharing(g, p));
    for (const auto& other : p.load_sharing) {
      const auto& last = p.load_sharing.back();
      if (&other != &last && other.first_axle < last.first_axle + last.axle_count &&
          last.first_axle < other.first_axle + other.axle_count)
        throw t.error("load_sharing", "an axle is in two [[load_sharing]] bogies");
    }
  }
}

VehicleParams load_vehicle_file(const std::filesystem::path& file,
                                const std::vector<Override>& patch) {
  toml::table root = load_toml_file(file);
  apply_overrides(patch, root, file);
  StrictTable t(root, file, "vehicle");
  VehicleParams p;
  p.name = t.string("name");
  read_chassis(t.table("chassis"), p.chassis);
  std::map<std::string, TireParams> tires;
  {
    StrictTable tt = t.table("tires");
    for (const auto& [key, node] : tt.raw()) {
      if (!node.is_table()) throw tt.error(key.str(), "must be a table of tire parameters");
      tires.emplace(std::string(key.str()), read_tire(tt.table(key.str())));
    }
    tt.finish();
  }
  std::vector<bool> caster_given;
  std::vector<StrictTable> axle_tables = t.tables("axle", model::kMaxWheelsPerUnit / 2);
  for (const auto& a : axle_tables) {
    caster_given.push_back(a.has("caster_trail_m"));
    p.axles.push_back(read_axle(a, tires));
  }
  if (p.axles.empty() || p.axles.size() > static_cast<std::size_t>(model::kMaxWheelsPerUnit / 2)) {
    throw t.error("axle", "needs 1 to 6 [[axle]] tables");
  }
  int leaf_axles = 0;
  for (std::size_t i = 0; i < p.axles.size(); ++i) {
    if (p.axles[i].has_leaf_spring && ++leaf_axles > model::vehicle::kMaxLeafAxles)
      throw axle_tables[i].error(
          "leaf_spring",
          "at most " + std::to_string(model::vehicle::kMaxLeafAxles) + " axles on leaf springs");
  }
  check_axle_order(axle_tables, p.axles);
  read_bogies(t, p);
  // A trailer (no steered, no driven axle) may leave out [steering] and [drivetrain].
  bool any_steered = false, any_driven = false;
  for (const auto& a : p.axles) {
    any_steered = any_steered || a.steered;
    any_driven = any_driven || a.driven;
  }
  if (auto s = t.optional_table("steering")) {
    // The old [steering] trail_m (one constant trail, pneumatic + caster) is still read: as the
    // caster trail of each steered axle without its own caster_trail_m; the pneumatic trail is
    // now the tire's, n(s_y) (model/tire aligning_torque_nm).
    if (const auto trail_m = read_steering(std::move(*s), p.steering)) {
      for (std::size_t i = 0; i < p.axles.size(); ++i)
        if (p.axles[i].steered && !caster_given[i]) p.axles[i].caster_trail_m = *trail_m;
    }
  } else if (any_steered) {
    throw t.error("steering", "a vehicle with a steered axle needs a [steering] table");
  }
  if (auto d = t.optional_table("drivetrain")) {
    read_drivetrain(std::move(*d), p.drivetrain, p.axles);
  } else if (any_driven) {
    throw t.error("drivetrain", "a vehicle with a driven axle needs a [drivetrain] table");
  }
  p.free_bodies = read_free_bodies(t);  // [[free_body]]: cab, engine, seat (none: empty)
  read_frame(t, p);                     // [frame]: frame torsion (none: one rigid chassis)
  t.finish();
  return p;
}

model::road::RoadParams read_road(StrictTable& m) {
  model::road::RoadParams r;
  r.grade = m.number_in("road_grade", 0, -1, 1);
  r.bank = m.number_in("road_bank", 0, -1, 1);
  r.friction = m.number_in("road_friction", 1.0, 0.05, 2);
  if (m.has("road_friction_right"))  // split mu: the right-hand wheels
    r.friction_right = m.number_in("road_friction_right", 0.05, 2);
  return r;
}

VehicleModelSettings read_vehicle_model(StrictTable& m, const std::vector<Override>& patch) {
  VehicleModelSettings v;
  v.file = m.existing_path("vehicle");
  v.params = load_vehicle_file(v.file, patch);
  // Alone on its axles (not in a combination) a vehicle stands only if its CG (x = 0) lies
  // between the first and the last axle.
  const auto& axles = v.params.axles;
  if (axles.size() < 2 || !(axles.front().position_x_m > 0 && axles.back().position_x_m < 0))
    throw m.error("vehicle", v.file.string() +
                                 ": a vehicle alone needs axles ahead of and behind its CG "
                                 "(position_x_m > 0 and < 0); a trailer runs in a combination");
  v.params.road = read_road(m);
  v.initial_speed_mps = m.number_in("initial_speed_mps", 0.0, -100, 100);
  v.params.slip_mask_speed_mps = m.number_in("slip_mask_speed_mps", 0.5, 0, 10);
  return v;
}

}  // namespace rig::io::config
