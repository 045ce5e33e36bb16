#pragma once
/// @file
/// A point mass on the framework's Jourdain columns (eq. 11, M = sum m J_v^T J_v): a wheel or a
/// rigid axle's half at r (body axes) moves with J_v = [I, -[r]x, g_1 .. g_N], the g_j its
/// velocity per framework coordinate idx[j] (hub travel, an axle's heave and roll, the frame's
/// twist). The one loop of the wheels behind the frame's split (independent: hub travel and twist;
/// rigid axle: heave, roll and twist). The rigid axle in front of the split
/// (VehicleFramework::rigid_mass_matrix) keeps its own 3 x 2 block form: it rounds m g_j . g_l
/// as (m g_j) . g_l where this loop rounds m (g_j . g_l), and the configs on rigid axles stay
/// bit-identical so.
#include <array>

#include <Eigen/Core>

#include "model/vehicle/chassis_kinematics.h"

namespace rig::model::vehicle {

/// M += mass J_v^T J_v with J_v = [I, -[r]x, cols] on the body's six columns and idx. Inlined
/// into its callers, as the loops it replaces were (a call costs ~100 instructions a wheel).
template <std::size_t N>
[[gnu::always_inline]] inline void add_point_mass(Eigen::MatrixXd& m, double mass_kg,
                                                  const Vec3& r_m,
                                                  const std::array<const Vec3*, N>& cols,
                                                  const std::array<Eigen::Index, N>& idx) noexcept {
  const Mat3 rx = skew(r_m);
  m.block<3, 3>(0, 0).diagonal().array() += mass_kg;
  m.block<3, 3>(0, 3) -= mass_kg * rx;
  m.block<3, 3>(3, 0) += mass_kg * rx;
  m.block<3, 3>(3, 3) += mass_kg * rx.transpose() * rx;
  for (std::size_t j = 0; j < N; ++j) {
    const Vec3& g = *cols[j];
    const Vec3 rxg = r_m.cross(g);
    m.block<3, 1>(0, idx[j]) += mass_kg * g;
    m.block<1, 3>(idx[j], 0) += mass_kg * g.transpose();
    m.block<3, 1>(3, idx[j]) += mass_kg * rxg;
    m.block<1, 3>(idx[j], 3) += mass_kg * rxg.transpose();
    for (std::size_t l = 0; l < N; ++l) m(idx[j], idx[l]) += mass_kg * g.dot(*cols[l]);
  }
}

}  // namespace rig::model::vehicle
