#pragma once
/// @file
/// The coupled pendulums of sec. 3.4 solved as an index-3 DAE: each pendulum is stepped by the
/// modified implicit Euler alone (z^u, mu), the rod by Newton on lambda (eqs. 45-50).

#include "model/paper/coupled_pendulums_params.h"
#include "model/paper/pendulum.h"
#include "model/paper/rod_constraint.h"
#include "model/solver/coupled_stepper.h"
#include "model/solver/mechanical_stepper.h"

namespace rig::model::paper {

/// Newton settings used for the pendulums: |g| <= 1e-7 m and the lambda increment below 1e-4 of
/// |lambda| (+1e-3 N) - the rod force to 0.01 %, which at h = 1 ms takes two iterations.
solver::NewtonParams default_pendulum_newton_params() noexcept;

/// How each pendulum is stepped between the Newton iterations on the rod force.
enum class PendulumScheme {
  /// The paper's listing (sec. 3.4, p_dyn/p_step): gravity is not stiff, so no Jacobians
  /// (M_VI = M) and q = -m g sin(phi) at y(k) - the symplectic Euler, which keeps the energy of
  /// the swing. The default: it agrees with the CVODE reference as the paper reports.
  kPaperListing,
  /// Eq. (8) in full: q at the predicted angle with dq/dphi in M_VI (linearized implicit Euler).
  /// Stable, but it damps the swing by O(h): at h = 1 ms the phase has drifted visibly by 5 s.
  kImplicit,
};

class CoupledPendulums {
 public:
  explicit CoupledPendulums(const CoupledPendulumsParams& params = {},
                            const solver::NewtonParams& newton = default_pendulum_newton_params(),
                            PendulumScheme scheme = PendulumScheme::kPaperListing);

  /// One step of size h; returns what Newton did. Never allocates.
  solver::NewtonReport step(double h) noexcept;

  [[nodiscard]] double time_s() const noexcept { return time_s_; }
  [[nodiscard]] double phi1_rad() const noexcept { return pendulum1_.angle_rad(); }
  [[nodiscard]] double phi2_rad() const noexcept { return pendulum2_.angle_rad(); }
  /// Generalized speeds v_i = a_i phi_i' [m/s].
  [[nodiscard]] double speed1_mps() const noexcept { return pendulum1_.speed_mps(); }
  [[nodiscard]] double speed2_mps() const noexcept { return pendulum2_.speed_mps(); }
  /// Kinetic + potential energy (pivots at height 0) [J].
  [[nodiscard]] double mechanical_energy_j() const noexcept;
  /// Rod force [N], tension positive (the multiplier is lambda = -tension: the generalized
  /// constraint force on v_i is (dl/dphi_i / a_i) lambda).
  [[nodiscard]] double rod_force_n() const noexcept { return -coupled_.multipliers()(0); }
  /// g = l - s at the current angles [m].
  [[nodiscard]] double constraint_violation_m() const noexcept;
  [[nodiscard]] double rod_length_m() const noexcept { return rod_length_m_; }
  [[nodiscard]] const CoupledPendulumsParams& params() const noexcept { return params_; }

 private:
  CoupledPendulumsParams params_;
  double rod_length_m_;
  Pendulum pendulum1_, pendulum2_;
  solver::MechanicalStepper<1> stepper1_, stepper2_;
  RodConstraint rod_;
  solver::CoupledStepper coupled_;
  double time_s_ = 0;
};

}  // namespace rig::model::paper
