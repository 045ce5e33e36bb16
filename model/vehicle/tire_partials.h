#pragma once
/// @file
/// The tire's force partials for the implicit step (eqs. 24, 31) of every wheel kind: force rows
/// at the wheel centre (J_C^T u), velocity rows at the contact point (u^T J_P), u = the normal
/// and the contact's ex, ey. Each wheel moves with the body's six columns and N columns of its
/// own (an independent wheel: its hub travel; a rigid axle: heave and roll; behind the frame's
/// split: and the twist), given as the contact point's velocity per unit rate g_j. The rows are
/// the same for every kind; only the columns and, for the rigid axles, the force on the moving
/// lever (added by the caller to dy with bk) differ.
#include <array>

#include <Eigen/Core>

#include "model/tire/tmeasy_tire.h"
#include "model/vehicle/chassis_kinematics.h"
#include "model/vehicle/wheel_contact.h"

namespace rig::model::vehicle {

/// The damping of the contact along the normal, ex and ey [N s/m]: the vertical damper and
/// eq. (24)'s damping paths at the slip's f.
[[nodiscard]] inline std::array<double, 3> tire_damping_nspm(
    const tire::TmeasyParams& t, const tire::TireCharacteristic& ch,
    const tire::TireKinematics& kin) noexcept {
  const tire::TireSlip slip = tire::slip_of(ch, kin, t.velocity_floor_mps);
  const tire::DampingPaths paths = tire::damping_paths(t, ch, kin, slip.f_per_slip);
  return {t.vertical_damping_nspm, paths.long_nspm, paths.lat_nspm};
}

/// The (6 + N) x (6 + N) blocks over [body 6, the wheel's N columns].
template <int N>
struct TirePartials {
  using Row = Eigen::Matrix<double, 6 + N, 1>;
  using Block = Eigen::Matrix<double, 6 + N, 6 + N>;
  Block dq_dz;
  Block dq_dy;
  Row pen_dy;  ///< -d penetration / d y = n^T J_P K (K = 1 on the wheel's own columns)
};

/// dq/dz: -sum_u d_u a_u b_u^T (a: J_C^T u, b: J_P^T u); dq/dy: -c_z a_n (n^T J_P K)^T.
/// centre_m: the wheel centre (body axes); cols: the contact point's g_j.
/// Inlined into each wheel kind's caller (as the four copies it replaces were written there): a
/// call costs the sedan ~290 instructions per wheel and step.
template <int N>
[[gnu::always_inline]] inline void tire_partials(const WheelContact& c, const Vec3& centre_m,
                                                 const std::array<const Vec3*, N>& cols,
                                                 const Mat3& rot, const Mat3& e_inv,
                                                 double vertical_stiffness_npm,
                                                 const std::array<double, 3>& damping_nspm,
                                                 TirePartials<N>& out) noexcept {
  using Row = typename TirePartials<N>::Row;
  constexpr auto n = static_cast<std::size_t>(N);
  const Vec3* dirs[3] = {&c.normal, &c.ex, &c.ey};
  out.dq_dz.setZero();
  for (std::size_t d = 0; d < 3; ++d) {
    const Vec3& u = *dirs[d];
    Row a, b;
    a.template head<3>() = u;
    a.template segment<3>(3) = centre_m.cross(u);
    for (std::size_t j = 0; j < n; ++j) a(static_cast<Eigen::Index>(6 + j)) = cols[j]->dot(u);
    b.template head<3>() = u;
    b.template segment<3>(3) = c.lever_m.cross(u);
    b.template tail<N>() = a.template tail<N>();
    out.dq_dz.noalias() -= (damping_nspm[d] * a) * b.transpose();
    if (d == 0) {
      // penetration rate = -n^T J_P z, and y' = K^-1 z: d pen / d y = -n^T J_P K
      out.pen_dy << rot * b.template head<3>(), e_inv.transpose() * b.template segment<3>(3),
          b.template tail<N>();
      out.dq_dy.noalias() = (-vertical_stiffness_npm * a) * out.pen_dy.transpose();
    }
  }
}

/// Adds a wheel's block (body 6, then its columns idx) into the framework's matrix.
template <int N, typename Matrix>
[[gnu::always_inline]] inline void scatter_tire_block(const typename TirePartials<N>::Block& blk,
                                                      const std::array<Eigen::Index, N>& idx,
                                                      Matrix& m) noexcept {
  constexpr auto n = static_cast<std::size_t>(N);
  m.template topLeftCorner<6, 6>() += blk.template topLeftCorner<6, 6>();
  for (std::size_t j = 0; j < n; ++j) {
    const auto bj = static_cast<Eigen::Index>(6 + j);
    m.template block<6, 1>(0, idx[j]) += blk.template block<6, 1>(0, bj);
    m.template block<1, 6>(idx[j], 0) += blk.template block<1, 6>(bj, 0);
    for (std::size_t l = 0; l < n; ++l)
      m(idx[j], idx[l]) += blk(bj, static_cast<Eigen::Index>(6 + l));
  }
}

}  // namespace rig::model::vehicle
