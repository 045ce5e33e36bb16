#pragma once
/// @file
/// The hand calculation of a vehicle's static axle loads (tests only): its frame, rigid, on its
/// axles' springs - each axle on its own (2 k at x), a leaf balance's two axles one support
/// (2 (k_1 + k_2) at x_g = w_1 x_1 + w_2 x_2, split w_1 : w_2 by the rocker's statics) - under
/// the frame's weight, the free bodies' and any extra load (a kingpin's): heave z and pitch p
/// from sum F = W, sum F x = M with F_j = c_j (z - x_j p) (Cramer). With two supports (a steer
/// axle and a balanced tandem) the rates drop out: the lever rule.
///
/// The rocker's statics, from the leaves' own parameters (not the model's code): the front
/// leaf puts s_1/L_1 of its seat load on its shackle pin, at x_1 - (L_1 - s_1) + l_sh sin(psi)
/// (the shackle hangs from the pin at psi from the vertical, > 0 with the eye behind the pin);
/// the rear leaf (L_2 - s_2)/L_2 on its front eye at x_2 + s_2; the rocker balances them by its
/// arms a_1 = pin - pivot, a_2 = pivot - eye: W_1 (s_1/L_1) a_1 = W_2 ((L_2 - s_2)/L_2) a_2.

#include <array>
#include <cmath>
#include <cstddef>

#include "model/vehicle/vehicle_params.h"

namespace rig::test {

/// Heave z [m] and pitch p [rad] of a rigid frame on springs c_j [N/m] at x_j under a vertical
/// load w [N] and moment m = sum W_i x_i [N m].
struct FrameOnSprings {
  double z_m = 0, pitch_rad = 0;
  [[nodiscard]] double force_n(double c, double x) const { return c * (z_m - x * pitch_rad); }
};
inline FrameOnSprings frame_on_springs(const double* c, const double* x, std::size_t n, double w,
                                       double m) {
  double c0 = 0, c1 = 0, c2 = 0;  // sum c, sum c x, sum c x^2
  for (std::size_t j = 0; j < n; ++j) {
    c0 += c[j];
    c1 += c[j] * x[j];
    c2 += c[j] * x[j] * x[j];
  }
  // [c0 -c1; c1 -c2] [z; p] = [w; m]
  const double det = -c0 * c2 + c1 * c1;
  return {(-w * c2 + c1 * m) / det, (c0 * m - c1 * w) / det};
}

/// The rocker's split of a leaf balance [w_1, w_2] (sum 1) from the leaves' parameters.
inline std::array<double, 2> leaf_balance_split(const model::vehicle::AxleParams& front,
                                                const model::vehicle::AxleParams& rear,
                                                double pivot_x_m) {
  const auto& f = front.leaf_spring;
  const auto& r = rear.leaf_spring;
  const double pin = front.position_x_m - (f.eye_to_eye_m - f.seat_from_front_eye_m) +
                     f.shackle_length_m * std::sin(f.shackle_angle_free_rad);
  const double eye = rear.position_x_m + r.seat_from_front_eye_m;
  const double a1 = pin - pivot_x_m, a2 = pivot_x_m - eye;
  const double share1 = f.seat_from_front_eye_m / f.eye_to_eye_m;
  const double share2 = (r.eye_to_eye_m - r.seat_from_front_eye_m) / r.eye_to_eye_m;
  const double w1 = share2 * a2, w2 = share1 * a1;  // W_1 / W_2 = share2 a2 / (share1 a1)
  return {w1 / (w1 + w2), w2 / (w1 + w2)};
}

/// Each axle's static spring load (both sides) [N] of `p` with `extra_n` [N] at `extra_x_m`
/// on its frame (a kingpin load; 0: solo). At most 6 axles, at most one leaf balance.
inline std::array<double, 6> static_spring_loads_n(const model::vehicle::VehicleParams& p,
                                                   double extra_n = 0, double extra_x_m = 0) {
  using model::vehicle::LoadSharingKind;
  const double g = p.road.gravity_mps2;
  double w = p.chassis.mass_kg * g + extra_n, m = extra_n * extra_x_m;
  for (const auto& b : p.free_bodies) {
    w += b.mass_kg * g;
    m += b.mass_kg * g * b.position_m[0];
  }
  int first = -1;  // the leaf balance's front axle
  std::array<double, 2> split{};
  for (const auto& s : p.load_sharing)
    if (s.kind == LoadSharingKind::kLeafBalance) {
      first = s.first_axle;
      const auto f = static_cast<std::size_t>(first);
      split = leaf_balance_split(p.axles[f], p.axles[f + 1], s.pivot_x_m);
    }
  std::array<double, 6> c{}, x{};
  std::size_t n = 0;
  for (std::size_t a = 0; a < p.axles.size(); ++a, ++n) {
    c[n] = 2 * p.axles[a].spring_stiffness_npm;
    x[n] = p.axles[a].position_x_m;
    if (static_cast<int>(a) == first) {  // the tandem: one support
      c[n] += 2 * p.axles[a + 1].spring_stiffness_npm;
      x[n] = split[0] * x[n] + split[1] * p.axles[a + 1].position_x_m;
      ++a;
    }
  }
  const FrameOnSprings f = frame_on_springs(c.data(), x.data(), n, w, m);
  std::array<double, 6> out{};
  for (std::size_t a = 0, j = 0; a < p.axles.size(); ++a, ++j) {
    out[a] = f.force_n(c[j], x[j]);
    if (static_cast<int>(a) == first) {
      out[a + 1] = split[1] * out[a];
      out[a] *= split[0];
      ++a;
    }
  }
  return out;
}

}  // namespace rig::test
