#pragma once
/// @file
/// The reference for the coupled pendulums (sec. 3.4): the same pendulums joined by a stiff
/// spring-damper rod instead of a constraint, integrated by SUNDIALS CVODE (BDF, Newton with a
/// dense direct solver, tight tolerances) - the paper used Matlab's ode15s.
///   m_i a_i^2 phi_i'' = -m_i g a_i sin(phi_i) - T dl/dphi_i,   T = c (l - s) + d l'
/// T is the rod force, tension positive (same sign as CoupledPendulums::rod_force_n()).
/// Test, benchmark and tool dependency only (rig/paper), never part of model/.

#include <memory>

#include "model/paper/coupled_pendulums_params.h"

namespace rig::paper {

struct SpringReferenceParams {
  double stiffness_npm = 5e7;   ///< c
  double damping_nspm = 1.5e4;  ///< d
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 1e-12;  ///< on angles [rad] and rates [rad/s]
};

class SpringReference {
 public:
  explicit SpringReference(const model::paper::CoupledPendulumsParams& pendulums = {},
                           const SpringReferenceParams& params = {});
  ~SpringReference();
  SpringReference(const SpringReference&) = delete;
  SpringReference& operator=(const SpringReference&) = delete;

  /// Integrates up to t_s (> time_s()); output interpolated by CVODE at exactly t_s.
  /// Throws std::runtime_error if CVODE fails.
  void advance_to(double t_s);

  [[nodiscard]] double time_s() const noexcept;
  [[nodiscard]] double phi1_rad() const noexcept;
  [[nodiscard]] double phi2_rad() const noexcept;
  /// T = c (l - s) + d l' [N], tension positive.
  [[nodiscard]] double rod_force_n() const noexcept;
  /// l - s [m].
  [[nodiscard]] double constraint_violation_m() const noexcept;
  /// Internal CVODE steps taken so far.
  [[nodiscard]] long steps() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rig::paper
