#include "model/vehicle/drivetrain.h"

#include <algorithm>
#include <cmath>

namespace rig::model::vehicle {
namespace {

double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  std::size_t i = 1;
  while (xs[i] < x) ++i;
  const double t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return ys[i - 1] + t * (ys[i] - ys[i - 1]);
}

}  // namespace

double engine_torque_nm(const DrivetrainParams& p, double throttle, double speed_radps) noexcept {
  // idle control: proportional throttle below idle speed; fuel cut above max speed
  const double idle =
      std::clamp(p.idle_gain_per_radps * (p.idle_speed_radps - speed_radps), 0.0, 1.0);
  double thr = std::max(std::clamp(throttle, 0.0, 1.0), idle);
  if (speed_radps > p.max_speed_radps) thr = 0;
  const double full = speed_radps > 0
                          ? interpolate(p.full_load_speed_radps, p.full_load_torque_nm, speed_radps)
                          : 0.0;
  const double drag = (p.drag_torque_nm + p.drag_torque_per_speed_nms * std::abs(speed_radps)) *
                      std::tanh(speed_radps / 5.0);
  return thr * full - (1.0 - thr) * drag;
}

double delivered_engine_torque_nm(const DrivetrainParams& p, double throttle, double speed_radps,
                                  double cut_nm) noexcept {
  const double te = engine_torque_nm(p, throttle, speed_radps);
  return std::max(te + cut_nm, std::min(te, engine_torque_nm(p, 0.0, speed_radps)));
}

double lockup_fraction(const DrivetrainParams& p, double turbine_radps) noexcept {
  return std::clamp((std::abs(turbine_radps) - p.lockup_start_radps) /
                        (p.lockup_full_radps - p.lockup_start_radps),
                    0.0, 1.0);
}

Drivetrain::Drivetrain(const DrivetrainParams& p, VehicleState& state, const VehicleInputs& inputs,
                       const VehicleWorkspace& work, const HalfShafts* shafts)
    : p_(p), state_(state), inputs_(inputs), work_(work), shafts_(shafts) {}

void Drivetrain::mass_matrix(const Vector& y, Matrix& m) const noexcept {
  (void)y;
  m << p_.engine_inertia_kgm2, 0, 0, p_.transmission_inertia_kgm2;
}

double Drivetrain::coupling_torque_nm(double engine_radps, double carrier_radps) const noexcept {
  if (work_.turbine_ratio == 0) return 0.0;
  const double slip = engine_radps - work_.turbine_ratio * carrier_radps;
  return (p_.converter_capacity_nms2 * std::abs(engine_radps) +
          work_.lockup_fraction * p_.lockup_damping_nms) *
         slip;
}

void Drivetrain::applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept {
  (void)y;
  const double te =
      delivered_engine_torque_nm(p_, inputs_.throttle, z(0), work_.engine_torque_cut_nm);
  const double tc = coupling_torque_nm(z(0), z(1));
  double shafts = 0;
  if (shafts_ != nullptr) {
    shafts = shafts_->count() * shafts_->shaft_torque_nm(shafts_->state_const(), z(1));
  }
  q(0) = te - tc;
  q(1) = p_.efficiency * work_.output_ratio * tc - shafts;
}

}  // namespace rig::model::vehicle
