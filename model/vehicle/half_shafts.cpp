#include "model/vehicle/half_shafts.h"

namespace rig::model::vehicle {

HalfShafts::HalfShafts(const DrivetrainParams& p, VehicleState& state, const VehicleWorkspace& work,
                       const std::array<int, kMaxWheels>& driven_wheels, int driven_count)
    : state_(state),
      work_(work),
      c_(p.half_shaft_stiffness_nmpr),
      d_(p.half_shaft_damping_nmspr),
      wheels_(driven_wheels),
      n_(driven_count) {}

double HalfShafts::shaft_torque_nm(const Vector& s, double carrier_radps) const noexcept {
  double sum_spin = 0;
  for (Eigen::Index i = 0; i < n_; ++i) {
    sum_spin += state_.spin_radps[static_cast<std::size_t>(wheels_[static_cast<std::size_t>(i)])];
  }
  const double n = static_cast<double>(n_);
  return (c_ * s.sum() + d_ * (n * carrier_radps - sum_spin)) / n;
}

void HalfShafts::rate(const Vector& s, Vector& f) const noexcept {
  const double t = shaft_torque_nm(s, work_.carrier_speed_radps);
  for (Eigen::Index i = 0; i < n_; ++i) f(i) = (t - c_ * s(i)) / d_;
}

bool HalfShafts::rate_jacobian(const Vector& s, Matrix& df_ds) const noexcept {
  (void)s;
  const double n = static_cast<double>(n_);
  df_ds.setConstant(c_ / (n * d_));
  for (Eigen::Index i = 0; i < n_; ++i) df_ds(i, i) -= c_ / d_;
  return true;
}

void HalfShafts::wheel_torques(double carrier_radps, double h,
                               std::array<double, kMaxWheels>& torque_nm,
                               std::array<double, kMaxWheels>& added_inertia_kgm2) const noexcept {
  const double t = shaft_torque_nm(state_const(), carrier_radps);
  const double added = h * d_torque_d_carrier() / static_cast<double>(count());
  for (Eigen::Index i = 0; i < n_; ++i) {
    const auto k = static_cast<std::size_t>(wheels_[static_cast<std::size_t>(i)]);
    torque_nm[k] = t;
    added_inertia_kgm2[k] = added;
  }
}

}  // namespace rig::model::vehicle
