#include "io/config/leaf_spring_config.h"

#include <stdexcept>
#include <string>

namespace rig::io::config {

namespace {

using model::vehicle::leaf_spring::LeafSpringParams;

/// The geometry the link model needs: two arms longer than 5 cm, a camber below half an arm.
void check_arms(StrictTable& t, const LeafSpringParams& p) {
  const double half_seat = 0.5 * p.seat_length_m;
  const double front = p.seat_from_front_eye_m - half_seat;
  const double rear = p.eye_to_eye_m - p.seat_from_front_eye_m - half_seat;
  if (!(front > 0.05 && rear > 0.05)) {
    throw t.error("seat_from_front_eye_m",
                  "leaves arms of " + std::to_string(front) + " m and " + std::to_string(rear) +
                      " m from the seat edges to the eyes: each must be longer than 0.05 m");
  }
  if (!(p.free_camber_m <= 0.5 * std::min(front, rear))) {
    throw t.error("free_camber_m", "must be at most half the shorter arm (" +
                                       std::to_string(0.5 * std::min(front, rear)) + " m)");
  }
}

void read_geometry(StrictTable& t, LeafSpringParams& p) {
  p.eye_to_eye_m = t.number_in("eye_to_eye_m", 0.2, 5.0);
  p.seat_from_front_eye_m = t.number_in("seat_from_front_eye_m", 0.05, 5.0);
  p.free_camber_m = t.number_in("free_camber_m", 0.001, 0.5);
  p.seat_length_m = t.number_in("seat_length_m", 0.0, 1.0);
  p.leaf_above_axle_m = t.number_in("leaf_above_axle_m", -1.0, 1.0);
  p.shackle_length_m = t.number_in("shackle_length_m", 0.02, 1.0);
  p.shackle_angle_free_rad = t.number_in("shackle_angle_free_rad", -1.2, 1.2);
}

void read_stiffness(StrictTable& t, LeafSpringParams& p) {
  p.front_bending_stiffness_nm2 = t.number_in("front_bending_stiffness_nm2", 1.0, 1e7);
  p.rear_bending_stiffness_nm2 = t.number_in("rear_bending_stiffness_nm2", 1.0, 1e7);
  p.eye_bushing_x_npm = t.number_in("eye_bushing_x_npm", 1e3, 1e10);
  p.eye_bushing_z_npm = t.number_in("eye_bushing_z_npm", 1e3, 1e10);
}

void read_solver(StrictTable& t, LeafSpringParams& p) {
  p.tolerance_nm = t.number_in("tolerance_nm", p.tolerance_nm, 1e-12, 1.0);
  p.closure_tolerance_m = t.number_in("closure_tolerance_m", p.closure_tolerance_m, 1e-15, 1e-3);
  p.max_iterations = static_cast<int>(t.integer_in("max_iterations", p.max_iterations, 1, 20));
}

}  // namespace

LeafSpringConfig read_leaf_spring(StrictTable& leaf) {
  LeafSpringConfig c;
  read_geometry(leaf, c.params);
  read_stiffness(leaf, c.params);
  read_solver(leaf, c.params);
  c.spring_track_m = leaf.number_in("spring_track_m", 0.2, 3.0);
  leaf.finish();
  check_arms(leaf, c.params);
  try {
    (void)model::vehicle::leaf_spring::make_leaf_geometry(c.params);  // the model's own checks
  } catch (const std::invalid_argument& e) {
    throw leaf.error(e.what());
  }
  return c;
}

std::optional<LeafSpringConfig> read_axle_leaf_spring(StrictTable& axle) {
  if (!axle.has("leaf_spring")) return std::nullopt;
  const StrictTable sub = axle.table("leaf_spring");
  StrictTable leaf(sub.raw(), axle.file(), "[axle.leaf_spring]");
  return read_leaf_spring(leaf);
}

LeafSpringConfig load_leaf_spring_file(const std::filesystem::path& file) {
  const toml::table root = load_toml_file(file);
  StrictTable top(root, file, "top");
  StrictTable axle = top.table("axle");
  std::optional<LeafSpringConfig> c = read_axle_leaf_spring(axle);
  if (!c) throw axle.error("leaf_spring", "missing required key");
  axle.finish();
  top.finish();
  return *c;
}

}  // namespace rig::io::config
