#pragma once
/// @file
/// The paper's sec. 3.4 example: two planar pendulums whose pivots are a horizontal distance b
/// apart, joined by a rigid rod between their bobs.

#include <numbers>

namespace rig::model::paper {

struct CoupledPendulumsParams {
  double length1_m = 1.0;                    ///< a1
  double length2_m = 1.5;                    ///< a2
  double pivot_distance_m = 1.5;             ///< b
  double mass1_kg = 10.0;                    ///< m1
  double mass2_kg = 5.0;                     ///< m2
  double gravity_mps2 = 9.81;                ///< g
  double phi1_0_rad = std::numbers::pi / 2;  ///< released at rest from 90 deg
  double phi2_0_rad = 0.0;
};

/// Rod geometry (sec. 3.4): bob distance l(phi1, phi2) and its partial derivatives.
struct RodGeometry {
  double x_m = 0;       ///< x = b + a2 sin(phi2) - a1 sin(phi1)
  double z_m = 0;       ///< z = a2 cos(phi2) - a1 cos(phi1)
  double length_m = 0;  ///< l = sqrt(x^2 + z^2)
  double dl_dphi1_m = 0;
  double dl_dphi2_m = 0;
};

/// l and its derivatives. The paper's listing has -a1*sin(phi2) in dg/dphi2's last term; the
/// correct term is -a2*sin(phi2) (method.md sec. 5).
RodGeometry rod_geometry(const CoupledPendulumsParams& p, double phi1_rad,
                         double phi2_rad) noexcept;

/// The rod length s fixed by the initial angles: sqrt(2.5) m for the paper's values.
double rod_length_m(const CoupledPendulumsParams& p) noexcept;

}  // namespace rig::model::paper
