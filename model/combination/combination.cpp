#include "model/combination/combination.h"

#include "model/combination/unit_reports.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rig::model::combination {

using vehicle::VehicleModel;
using vehicle::VehicleParams;

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
    units[k] = std::make_unique<VehicleModel>(p, step_size_s);
    hitch_load_n = held ? units[k]->framework().support_load_n() : 0.0;
  }
  return units;
}

void place_units(std::vector<std::unique_ptr<VehicleModel>>& units,
                 const std::vector<JointParams>& joints, double x_m, double y_m, double yaw_rad) {
  const Vec3 ex(std::cos(yaw_rad), std::sin(yaw_rad), 0);
  double x = x_m, y = y_m;
  units[0]->reset(x, y, yaw_rad);
  for (std::size_t k = 0; k + 1 < units.size(); ++k) {
    // in line: the hitch point of unit k and of unit k+1 coincide in the road plane
    double dx = joints[k].leading_point_m.x() - joints[k].trailing_point_m.x();
    if (joints[k].kind == JointKind::kTowBar) {
      // the rod points straight back; its horizontal length from the ends' design heights
      const double dz =
          (joints[k].leading_point_m.z() + units[k]->params().chassis.cg_height_m) -
          (joints[k].trailing_point_m.z() + units[k + 1]->params().chassis.cg_height_m);
      const double l = joints[k].length_m;
      dx -= std::sqrt(std::max(l * l - dz * dz, 0.0));
    }
    x += dx * ex.x();
    y += dx * ex.y();
    units[k + 1]->reset(x, y, yaw_rad);
  }
}

Combination::Combination(const CombinationParams& params, double step_size_s)
    : p_(params), h_(step_size_s), units_(build_units(params, step_size_s)) {
  std::vector<Eigen::Index> sizes;
  for (const auto& u : units_) sizes.push_back(u->coordinate_size());
  constraint_ = std::make_unique<ChainConstraint>(p_.joints, sizes);
  std::vector<solver::CouplableSystem*> systems;
  for (auto& u : units_) systems.push_back(u.get());
  if (p_.parallel) {
    if (!p_.begin_step_runner) {
      throw std::invalid_argument("combination " + p_.name +
                                  ": parallel = true needs a begin_step_runner");
    }
    parallel_ = p_.begin_step_runner(
        std::vector<solver::CouplableSystem*>(systems.begin() + 1, systems.end()));
  }
  stepper_ =
      std::make_unique<ChainStepper>(std::move(systems), *constraint_, p_.newton, parallel_.get());
  saved_lambda_ = Eigen::VectorXd::Zero(constraint_->size());
  // warm start of the very first step: the static hitch loads (down on the leading unit)
  static_lambda_ = Eigen::VectorXd::Zero(constraint_->size());
  for (int i = 0; i < constraint_->joint_count(); ++i) {
    if (constraint_->joint(i).params().kind == JointKind::kTowBar) continue;  // no static load
    static_lambda_(constraint_->row(i) + 2) =
        -units_[static_cast<std::size_t>(i) + 1]->framework().support_load_n();
  }
  reset(0, 0, 0);
}

Combination::~Combination() = default;

void Combination::reset(double x_m, double y_m, double yaw_rad) noexcept {
  place_units(units_, p_.joints, x_m, y_m, yaw_rad);
  stepper_->set_multipliers(static_lambda_);
  time_s_ = 0;
}

void Combination::set_forward_speed(double speed_mps) noexcept {
  for (auto& u : units_) u->set_forward_speed(speed_mps);
}

StepStatus Combination::step(Signals& signals) noexcept {
  for (auto& u : units_) u->set_inputs(signals);
  saved_lambda_ = stepper_->multipliers();
  stepper_->step(h_);  // eqs. (45-50)
  bool ok = stepper_->multipliers().allFinite();
  for (const auto& u : units_) ok = ok && u->last_status() == StepStatus::kOk;
  if (!ok) {
    for (auto& u : units_) u->revert_step();  // all units back to t (no-op where undone)
    stepper_->set_multipliers(saved_lambda_);
    return StepStatus::kNonFinite;
  }
  time_s_ += h_;
  units_[0]->write_outputs(signals);
  return StepStatus::kOk;
}

Vec3 Combination::joint_force_n(int i) const noexcept {
  const Joint& j = constraint_->joint(i);
  if (j.params().kind == JointKind::kTowBar) {
    // -lambda u: (dg/dr_a)^T lambda at the current coordinates
    JointEvaluation e;
    const auto k = static_cast<std::size_t>(i);
    j.evaluate(units_[k]->coordinates().head<6>(), units_[k + 1]->coordinates().head<6>(), e);
    return e.dg_dya.block<1, 3>(0, 0).transpose() * stepper_->multipliers()(constraint_->row(i));
  }
  return Joint::force_on_leading_n(stepper_->multipliers().segment(constraint_->row(i), 3));
}

double Combination::rod_force_n(int i) const noexcept {
  if (constraint_->joint(i).params().kind != JointKind::kTowBar) return 0;
  return Joint::rod_force_n(stepper_->multipliers()(constraint_->row(i)));
}

double Combination::joint_violation_m(int i) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  return combination::joint_violation_m(constraint_->joint(i), *units_[k], *units_[k + 1]);
}

double Combination::articulation_rad(int i) const noexcept {
  const auto k = static_cast<std::size_t>(i);
  return combination::articulation_rad(*units_[k], *units_[k + 1]);
}

void Combination::fill_report(ModelReport& report) const noexcept {
  fill_unit_reports(units_, report);
  report.time_s = time_s_;
  report.joint_count = std::min(constraint_->joint_count(), kMaxJoints);
  for (int i = 0; i < report.joint_count; ++i) {
    JointReport& j = report.joints[static_cast<std::size_t>(i)];
    const Vec3 f = joint_force_n(i);
    j.force_n = {f.x(), f.y(), f.z()};
    j.violation_m = joint_violation_m(i);
    j.rod_force_n = rod_force_n(i);
    j.newton_iterations = stepper_->last_report().iterations;
  }
}

}  // namespace rig::model::combination
