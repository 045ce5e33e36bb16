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

double engine_drag_nm(const DrivetrainParams& p, double speed_radps) noexcept {
  return (p.drag_torque_nm + p.drag_torque_per_speed_nms * std::abs(speed_radps)) *
         std::tanh(speed_radps / 5.0);
}

double engine_torque_nm(const DrivetrainParams& p, double throttle, double speed_radps) noexcept {
  // idle control: proportional throttle below idle speed; fuel cut above max speed
  const double idle =
      std::clamp(p.idle_gain_per_radps * (p.idle_speed_radps - speed_radps), 0.0, 1.0);
  double thr = std::max(std::clamp(throttle, 0.0, 1.0), idle);
  if (speed_radps > p.max_speed_radps) thr = 0;
  const double full = speed_radps > 0
                          ? interpolate(p.full_load_speed_radps, p.full_load_torque_nm, speed_radps)
                          : 0.0;
  return thr * full - (1.0 - thr) * engine_drag_nm(p, speed_radps);
}

double delivered_engine_torque_nm(const DrivetrainParams& p, double throttle, double speed_radps,
                                  double cut_nm, bool running) noexcept {
  if (!running) return -engine_drag_nm(p, speed_radps);
  const double te = engine_torque_nm(p, throttle, speed_radps);
  return std::max(te + cut_nm, std::min(te, engine_torque_nm(p, 0.0, speed_radps)));
}

double lockup_fraction(const DrivetrainParams& p, double turbine_radps,
                       double engine_radps) noexcept {
  const double by_speed = std::clamp((std::abs(turbine_radps) - p.lockup_start_radps) /
                                         (p.lockup_full_radps - p.lockup_start_radps),
                                     0.0, 1.0);
  if (by_speed == 0.0) return 0.0;
  // near coupling: the turbine within (1 - ratio) of the engine speed
  const double ratio = std::abs(turbine_radps) / std::max(std::abs(engine_radps), 1.0);
  return by_speed * std::clamp((ratio - p.lockup_speed_ratio_start) /
                                   (p.lockup_speed_ratio_full - p.lockup_speed_ratio_start),
                               0.0, 1.0);
}

Drivetrain::Drivetrain(const DrivetrainParams& p, VehicleState& state, const VehicleInputs& inputs,
                       const VehicleWorkspace& work, const DrivenShafts* shafts)
    : p_(p),
      state_(state),
      inputs_(inputs),
      work_(work),
      shafts_(shafts),
      lockup_capacity_(p.lockup_capacity_nm > 0 ? p.lockup_capacity_nm
                                                : *std::max_element(p.full_load_torque_nm.begin(),
                                                                    p.full_load_torque_nm.end())) {}

void Drivetrain::mass_matrix(const Vector& y, Matrix& m) const noexcept {
  (void)y;
  m << p_.engine_inertia_kgm2, 0, 0, p_.transmission_inertia_kgm2;
}

double Drivetrain::coupling_torque_nm(double engine_radps, double carrier_radps) const noexcept {
  if (work_.turbine_ratio == 0) return 0.0;
  const double slip = engine_radps - work_.turbine_ratio * carrier_radps;
  // the lock-up clutch: a stiff damper while it holds, at most its capacity while it slips
  const double capacity = work_.lockup_fraction * lockup_capacity_;
  const double lockup =
      std::clamp(work_.lockup_fraction * p_.lockup_damping_nms * slip, -capacity, capacity);
  return p_.converter_capacity_nms2 * std::abs(engine_radps) * slip + lockup;
}

void Drivetrain::applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept {
  (void)y;
  const double te = delivered_engine_torque_nm(p_, inputs_.throttle, z(0),
                                               work_.engine_torque_cut_nm, inputs_.ignition_on);
  const double tc = coupling_torque_nm(z(0), z(1));
  double shafts = 0;
  if (shafts_ != nullptr) shafts = shafts_->carrier_torque_nm(z(1));
  q(0) = te - tc;
  q(1) = p_.efficiency * work_.output_ratio * tc - shafts;
}

}  // namespace rig::model::vehicle
