#pragma once
/// @file
/// The TMeasy tire as a solver force element (method.md eq. 8, first line): states
/// s = (x_e, y_e), rate f = (x_e', y_e') of eq. (24) and its lateral twin, df/ds diagonal, and
/// the eq. (26) clamp after the implicit update. The owner (vehicle, quarter car) writes the
/// current TireInput into input() before each step; force() then gives F_x, F_y and their
/// partials at the newest state for the framework's q and M_VI.

#include "model/solver/force_element.h"
#include "model/tire/tmeasy_tire.h"

namespace rig::model::tire {

class TmeasyForceElement final : public solver::ForceElement<2> {
 public:
  explicit TmeasyForceElement(const TmeasyParams& params = default_215_55_r18()) noexcept
      : tire_(params) {}

  /// The inputs of the next evaluation (contact velocities, spin, r_D, F_z, mu).
  [[nodiscard]] TireInput& input() noexcept { return input_; }
  [[nodiscard]] const TmeasyTire& tire() const noexcept { return tire_; }

  [[nodiscard]] Eigen::Index state_size() const noexcept override { return 2; }
  [[nodiscard]] Vector& state() noexcept override { return s_; }

  /// f = (x_e', y_e') at s (eq. 24, limiter eq. 26, lift-off relaxation).
  void rate(const Vector& s, Vector& f) const noexcept override {
    f = evaluate_cached(s).deflection_rate;
  }
  /// df/ds = diag(d x_e'/d x_e, d y_e'/d y_e).
  bool rate_jacobian(const Vector& s, Matrix& df_ds) const noexcept override {
    df_ds.setZero();
    df_ds.diagonal() = evaluate_cached(s).d_rate_d_deflection;
    return true;
  }
  /// Eq. (26) after the update: clamp the deflection to F_M / c.
  void after_update(Vector& s) noexcept override {
    TireDeflection d{s(0), s(1)};
    tire_.clamp_deflection(input_.load_n, input_.friction, d);
    s = {d.long_m, d.lat_m};
  }

  /// Forces, torques and partials at the current state and input.
  void force(TireOutput& out) const noexcept { out = evaluate_cached(s_); }

 private:
  // The stepper asks for df/ds and f at the same s: evaluate once (keyed by s and the input).
  const TireOutput& evaluate_cached(const Vector& s) const noexcept {
    const bool same_input = cached_input_.long_speed_mps == input_.long_speed_mps &&
                            cached_input_.lat_speed_mps == input_.lat_speed_mps &&
                            cached_input_.spin_radps == input_.spin_radps &&
                            cached_input_.rolling_radius_m == input_.rolling_radius_m &&
                            cached_input_.load_n == input_.load_n &&
                            cached_input_.friction == input_.friction;
    if (!cache_valid_ || !same_input || s != cached_s_) {
      tire_.evaluate(input_, TireDeflection{s(0), s(1)}, cached_);
      cached_input_ = input_;
      cached_s_ = s;
      cache_valid_ = true;
    }
    return cached_;
  }

  TmeasyTire tire_;
  TireInput input_;
  Vector s_ = Vector::Zero();
  mutable TireOutput cached_;
  mutable TireInput cached_input_;
  mutable Vector cached_s_ = Vector::Zero();
  mutable bool cache_valid_ = false;
};

}  // namespace rig::model::tire
