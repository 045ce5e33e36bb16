#include "model/combination/combination_shell.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "model/combination/combination_hold.h"

namespace rig::model::combination {
namespace {

using vehicle::VehicleModel;
using vehicle::VehicleParams;

/// The units back to front, so that each spring preload includes the static hitch loads.
std::vector<std::unique_ptr<VehicleModel>> build_units(const CombinationParams& params,
                                                       double step_size_s) {
  const std::size_t n = params.units.size();
  if (n < 2) throw std::invalid_argument("combination: needs at least two units");
  if (params.joints.size() != n - 1)
    throw std::invalid_argument("combination: needs one joint between each pair of units");
  std::vector<std::unique_ptr<VehicleModel>> units(n);
  double hitch_load_n = 0;  // static vertical load of unit i+1 on unit i (down on i)
  for (std::size_t k = n; k-- > 0;) {
    VehicleParams p = params.units[k];
    // a tow bar (pinned rod, level in the design position) carries no static vertical load:
    // the towed unit stands on its own axles
    if (k + 1 < n && params.joints[k].kind != JointKind::kTowBar) {
      // carries the next unit's static hitch load
      p.chassis.payload_n = hitch_load_n;
      p.chassis.payload_x_m = params.joints[k].leading_point_m.x();
    }
    const bool held = k > 0 && params.joints[k - 1].kind != JointKind::kTowBar;
    if (held) {  // held at its hitch by the unit in front
      p.chassis.supported = true;
      p.chassis.support_x_m = params.joints[k - 1].trailing_point_m.x();
    }
    units[k] = std::make_unique<VehicleModel>(p, step_size_s, static_cast<int>(k));
    hitch_load_n = held ? units[k]->framework().support_load_n() : 0.0;
  }
  return units;
}

std::vector<Eigen::Index> unit_sizes(const std::vector<std::unique_ptr<VehicleModel>>& units) {
  std::vector<Eigen::Index> sizes;
  sizes.reserve(units.size());
  for (const auto& u : units) sizes.push_back(u->coordinate_size());
  return sizes;
}

}  // namespace

solver::NewtonParams default_combination_newton_params() noexcept {
  solver::NewtonParams p;
  p.criterion = solver::NewtonCriterion::kPositionAndMultiplier;
  p.position_tolerance = 1e-7;
  p.multiplier_rel_tolerance = 1e-3;
  p.multiplier_abs_tolerance = 1.0;
  p.max_iterations = 10;
  return p;
}

JointParams make_joint_params(JointKind kind, const VehicleParams& leading, double leading_x_m,
                              const VehicleParams& trailing, double trailing_x_m, double height_m) {
  JointParams j;
  j.kind = kind;
  j.leading_point_m = Vec3(leading_x_m, 0, height_m - leading.chassis.cg_height_m);
  j.trailing_point_m = Vec3(trailing_x_m, 0, height_m - trailing.chassis.cg_height_m);
  return j;
}

CombinationShell::CombinationShell(const CombinationParams& params, double step_size_s)
    : p_(params),
      h_(step_size_s),
      units_(build_units(params, step_size_s)),
      constraint_(std::make_unique<ChainConstraint>(p_.joints, unit_sizes(units_))) {}

void CombinationShell::reset(double x_m, double y_m, double yaw_rad) noexcept {
  const Vec3 ex(std::cos(yaw_rad), std::sin(yaw_rad), 0);
  double x = x_m, y = y_m;
  units_[0]->reset(x, y, yaw_rad);
  for (std::size_t k = 0; k + 1 < units_.size(); ++k) {
    const JointParams& j = p_.joints[k];
    // in line: the hitch point of unit k and of unit k+1 coincide in the road plane
    double dx = j.leading_point_m.x() - j.trailing_point_m.x();
    if (j.kind == JointKind::kTowBar) {
      // the rod points straight back; its horizontal length from the ends' design heights
      const double dz = (j.leading_point_m.z() + units_[k]->params().chassis.cg_height_m) -
                        (j.trailing_point_m.z() + units_[k + 1]->params().chassis.cg_height_m);
      const double l = j.length_m;
      dx -= std::sqrt(std::max(l * l - dz * dz, 0.0));
    }
    x += dx * ex.x();
    y += dx * ex.y();
    units_[k + 1]->reset(x, y, yaw_rad);
  }
  reset_coupling();
  time_s_ = 0;
}

void CombinationShell::set_forward_speed(double speed_mps) noexcept {
  for (auto& u : units_) u->set_forward_speed(speed_mps);
}

vehicle::Equilibrium CombinationShell::settle(double speed_mps, int gear_request) {
  std::vector<vehicle::VehicleModel::Pose> poses;
  poses.reserve(units_.size());
  for (auto& u : units_) poses.push_back(u->begin_settle(speed_mps));
  vehicle::Equilibrium e = vehicle::settle_loop(
      h_, speed_mps, gear_request, [&](Signals& s) { return step(s) == StepStatus::kOk; },
      [&] { hold_in_line(units_, p_.joints, speed_mps); },
      [&] { return units_[0]->state().acceleration_mps2.x(); });
  // back by one translation (the leading unit's): the settled heave and pitch moved the hitch
  // points, the units' own start poses would no longer meet the joints
  const vehicle::VehicleState& lead = units_[0]->state();
  const double dx = lead.framework_y(0) - poses[0].x_m, dy = lead.framework_y(1) - poses[0].y_m;
  for (std::size_t k = 0; k < units_.size(); ++k) {
    const vehicle::VehicleState& u = units_[k]->state();
    units_[k]->end_settle({u.framework_y(0) - dx, u.framework_y(1) - dy, poses[k].yaw_rad},
                          speed_mps);
  }
  time_s_ = 0;
  e.gear = units_[0]->state().gear;
  return e;
}

StepStatus CombinationShell::step(Signals& signals) noexcept {
  for (auto& u : units_) u->set_inputs(signals);
  fault_ = first_fault(couple(h_));
  if (fault_.kind != FaultKind::kNone) {
    for (auto& u : units_) u->revert_step();  // all units back to t (no-op where undone)
    revert_coupling();
    return step_status(fault_.kind);
  }
  time_s_ += h_;
  units_[0]->write_outputs(signals);
  return StepStatus::kOk;
}

ModelFault CombinationShell::first_fault(bool coupled) const noexcept {
  for (std::size_t k = 0; k < units_.size(); ++k) {
    if (units_[k]->last_status() == StepStatus::kOk) continue;
    ModelFault f = units_[k]->last_fault();
    if (f.kind == FaultKind::kNone) f.kind = FaultKind::kNonFinite;
    f.unit = static_cast<std::int32_t>(k);
    return f;
  }
  if (coupled) return {};
  ModelFault f;
  f.kind = FaultKind::kNonFinite;
  f.unit = -1;
  f.time_s = time_s_ + h_;
  f.value = std::numeric_limits<double>::quiet_NaN();
  return f;
}

double CombinationShell::joint_violation_m(int i) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  const Joint& joint = constraint_->joint(i);
  JointEvaluation e;
  joint.evaluate(units_[k]->coordinates().head<6>(), units_[k + 1]->coordinates().head<6>(), e);
  return e.g.head(joint.size()).lpNorm<Eigen::Infinity>();
}

double CombinationShell::articulation_rad(int i) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  return std::remainder(units_[k]->coordinates()(3) - units_[k + 1]->coordinates()(3),
                        2 * std::numbers::pi);
}

void CombinationShell::fill_report(ModelReport& report) const noexcept {
  // unit 0 fills the whole report (signals, unit 0, its wheels), every further unit its entry
  units_[0]->fill_report(report);
  const int n = std::min(static_cast<int>(units_.size()), kMaxUnits);
  ModelReport unit_report;  // scratch on the stack: no allocation
  for (int k = 1; k < n; ++k) {
    units_[static_cast<std::size_t>(k)]->fill_report(unit_report);
    report.units[static_cast<std::size_t>(k)] = unit_report.units[0];
  }
  report.unit_count = n;
  report.time_s = time_s_;
  report.joint_count = std::min(constraint_->joint_count(), kMaxJoints);
  for (int i = 0; i < report.joint_count; ++i) {
    JointReport& j = report.joints[static_cast<std::size_t>(i)];
    const Vec3 f = joint_force_n(i);
    j.force_n = {f.x(), f.y(), f.z()};
    j.violation_m = joint_violation_m(i);
    j.rod_force_n = rod_force_n(i);
    j.newton_iterations = newton_iterations();
  }
}

}  // namespace rig::model::combination
