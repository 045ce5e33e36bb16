#include "model/combination/combination.h"

#include <stdexcept>

namespace rig::model::combination {

Combination::Combination(const CombinationParams& params, double step_size_s)
    : CombinationShell(params, step_size_s) {
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

void Combination::reset_coupling() noexcept { stepper_->set_multipliers(static_lambda_); }

bool Combination::couple(double h) noexcept {
  saved_lambda_ = stepper_->multipliers();
  stepper_->step(h);  // eqs. (45-50)
  return stepper_->multipliers().allFinite();
}

void Combination::revert_coupling() noexcept { stepper_->set_multipliers(saved_lambda_); }

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

}  // namespace rig::model::combination
