#pragma once
/// @file
/// The TMeasy tire as a solver force element (eq. 3; advanced by eq. 8, first line): states
/// s = (x_e, y_e), rate eq. (24) and its lateral twin with f frozen at the start of the step,
/// df/ds diagonal, and eq. (26) on the state after the implicit update (limit_deflection). The
/// owner keeps the states in its one state struct and writes the step's TireContact before the
/// stage runs; the forces then come from tire_forces() at the newest state.

#include "model/solver/force_element.h"
#include "model/tire/tmeasy_tire.h"

namespace rig::model::tire {

class TmeasyForceElement final : public solver::ForceElement<2> {
 public:
  /// params, contact and state must outlive the element (they belong to its owner).
  TmeasyForceElement(const TmeasyParams& params, const TireContact& contact, Vector& state) noexcept
      : params_(params), contact_(contact), state_(state) {}

  [[nodiscard]] Eigen::Index state_size() const noexcept override { return 2; }
  [[nodiscard]] Vector& state() noexcept override { return state_; }
  /// f = (x_e', y_e'), eq. (24) at the step's contact.
  void rate(const Vector& s, Vector& f) const noexcept override {
    f = deflection_rates(params_, contact_.characteristic, contact_.kinematics, contact_.f_per_slip,
                         s)
            .rate;
  }
  /// df/ds = diag(dx_e'/dx_e, dy_e'/dy_e).
  bool rate_jacobian(const Vector& s, Matrix& df_ds) const noexcept override {
    const DeflectionRates r = deflection_rates(params_, contact_.characteristic,
                                               contact_.kinematics, contact_.f_per_slip, s);
    df_ds << r.d_rate_d_deflection(0), 0, 0, r.d_rate_d_deflection(1);
    return true;
  }
  /// Eq. (26) after the update: the spring force stays within the ellipse of the maxima (times
  /// the sliding ratio of the step's slip).
  void after_update(Vector& s) noexcept override {
    limit_deflection(params_, contact_.characteristic, contact_.sliding_ratio, s);
  }

 private:
  const TmeasyParams& params_;
  const TireContact& contact_;
  Vector& state_;
};

}  // namespace rig::model::tire
