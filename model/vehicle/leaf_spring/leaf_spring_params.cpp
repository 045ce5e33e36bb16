#include "model/vehicle/leaf_spring/leaf_spring_params.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rig::model::vehicle::leaf_spring {

namespace {

void require(bool ok, const char* field, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("leaf spring ") + field + ": " + what);
}

void check(const LeafSpringParams& p) {
  require(std::isfinite(p.eye_to_eye_m) && p.eye_to_eye_m > 0.1 && p.eye_to_eye_m < 5.0,
          "eye_to_eye_m", "must lie in (0.1, 5) m");
  const double front = p.seat_from_front_eye_m - 0.5 * p.seat_length_m;
  const double rear = p.eye_to_eye_m - p.seat_from_front_eye_m - 0.5 * p.seat_length_m;
  require(std::isfinite(p.seat_length_m) && p.seat_length_m >= 0.0, "seat_length_m",
          "must be >= 0");
  require(std::isfinite(front) && front > 0.05 && std::isfinite(rear) && rear > 0.05,
          "seat_from_front_eye_m", "each arm (seat edge to eye) must be longer than 0.05 m");
  require(std::isfinite(p.free_camber_m) && p.free_camber_m >= 1e-3 &&
              p.free_camber_m <= 0.5 * std::min(front, rear),
          "free_camber_m", "must lie in [0.001 m, half the shorter arm]");
  require(std::isfinite(p.leaf_above_axle_m) && std::abs(p.leaf_above_axle_m) < 1.0,
          "leaf_above_axle_m", "must lie in (-1, 1) m");
  require(p.front_bending_stiffness_nm2 > 0 && std::isfinite(p.front_bending_stiffness_nm2),
          "front_bending_stiffness_nm2", "must be finite and > 0");
  require(p.rear_bending_stiffness_nm2 > 0 && std::isfinite(p.rear_bending_stiffness_nm2),
          "rear_bending_stiffness_nm2", "must be finite and > 0");
  require(p.shackle_length_m > 0.01 && p.shackle_length_m < 1.0, "shackle_length_m",
          "must lie in (0.01, 1) m");
  require(std::abs(p.shackle_angle_free_rad) < 1.2, "shackle_angle_free_rad",
          "must lie in (-1.2, 1.2) rad");
  require(p.eye_bushing_x_npm > 0 && std::isfinite(p.eye_bushing_x_npm), "eye_bushing_x_npm",
          "must be finite and > 0");
  require(p.eye_bushing_z_npm > 0 && std::isfinite(p.eye_bushing_z_npm), "eye_bushing_z_npm",
          "must be finite and > 0");
  require(p.tolerance_nm > 0 && p.closure_tolerance_m > 0, "tolerance", "must be > 0");
  require(p.max_iterations >= 1 && p.max_iterations <= 20, "max_iterations", "must be in [1, 20]");
}

/// One arm: a circular arc of horizontal span `span` rising `rise`, leaving the seat edge
/// horizontally in direction `dir` (+1 forward, -1 rearward). Returns A (at 2/3 of the arc from
/// the seat edge) and the eye; sets the arc length.
struct ArmPoints {
  Eigen::Vector2d joint;
  Eigen::Vector2d eye;
  double arc_m;
};

ArmPoints arm_points(const Eigen::Vector2d& edge, double span, double rise, double dir) {
  const double radius = (span * span + rise * rise) / (2.0 * rise);
  const double end_rad = std::atan2(span, radius - rise);
  const auto at = [&](double phi) {
    return Eigen::Vector2d(edge.x() + dir * radius * std::sin(phi),
                           edge.y() + radius * (1.0 - std::cos(phi)));
  };
  const Eigen::Vector2d joint = at(2.0 / 3.0 * end_rad);
  const Eigen::Vector2d eye = at(end_rad);
  const double arc = radius * end_rad;
  // Bulge the joint away from the chord S-E until the two links are as long as the arc: the
  // eye then travels as far as the beam's when the arm flattens (the chords alone are ~8 %
  // short of the arc's excess length over its chord).
  const Eigen::Vector2d chord = eye - edge;
  const Eigen::Vector2d away = Eigen::Vector2d(chord.y(), -chord.x()).normalized() * dir;
  double lo = -0.5 * rise;
  double hi = 0.5 * rise;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    const Eigen::Vector2d a = joint + mid * away;
    ((a - edge).norm() + (eye - a).norm() < arc ? lo : hi) = mid;
  }
  return {joint + 0.5 * (lo + hi) * away, eye, arc};
}

double angle_of(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  return std::atan2(to.y() - from.y(), to.x() - from.x());
}

}  // namespace

LeafGeometry make_leaf_geometry(const LeafSpringParams& p) {
  check(p);
  LeafGeometry g;
  const double h = p.leaf_above_axle_m;
  const double half_seat = 0.5 * p.seat_length_m;
  g.seat_front_m = {half_seat, h};
  g.seat_rear_m = {-half_seat, h};
  const double front_span = p.seat_from_front_eye_m - half_seat;
  const double rear_span = p.eye_to_eye_m - p.seat_from_front_eye_m - half_seat;
  const ArmPoints f = arm_points(g.seat_front_m, front_span, p.free_camber_m, 1.0);
  const ArmPoints r = arm_points(g.seat_rear_m, rear_span, p.free_camber_m, -1.0);
  g.front_inner_m = (f.joint - g.seat_front_m).norm();
  g.front_outer_m = (f.eye - f.joint).norm();
  g.rear_inner_m = (r.joint - g.seat_rear_m).norm();
  g.rear_outer_m = (r.eye - r.joint).norm();
  g.free_angle_rad << angle_of(g.seat_front_m, f.joint), angle_of(f.joint, f.eye),
      angle_of(g.seat_rear_m, r.joint), angle_of(r.joint, r.eye);
  g.front_arc_m = f.arc_m;
  g.rear_arc_m = r.arc_m;
  const double ei_f = p.front_bending_stiffness_nm2;
  const double ei_r = p.rear_bending_stiffness_nm2;
  g.spring_nmprad << 4.0 * ei_f / f.arc_m, 4.0 * ei_f / (3.0 * f.arc_m), 4.0 * ei_r / r.arc_m,
      4.0 * ei_r / (3.0 * r.arc_m);
  g.eye_frame_m = f.eye;
  g.shackle_length_m = p.shackle_length_m;
  g.shackle_angle_free_rad = p.shackle_angle_free_rad;
  g.pin_frame_m = r.eye + p.shackle_length_m * Eigen::Vector2d(std::sin(p.shackle_angle_free_rad),
                                                               std::cos(p.shackle_angle_free_rad));
  g.bushing_npm = {p.eye_bushing_x_npm, p.eye_bushing_z_npm};
  return g;
}

}  // namespace rig::model::vehicle::leaf_spring
