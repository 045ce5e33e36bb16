#include "model/solver/sequential_stepper.h"

namespace rig::model::solver {

SequentialStepper::SequentialStepper(CouplableSystem& framework)
    : framework_(framework), zero_rate_(Eigen::VectorXd::Zero(framework.coordinate_size())) {}

void SequentialStepper::add_stage(Stage& stage) { stages_.push_back(&stage); }

void SequentialStepper::step(double h) noexcept {
  begin_step(h);
  framework_.finish_step(h, zero_rate_);
}

Eigen::Index SequentialStepper::coordinate_size() const noexcept {
  return framework_.coordinate_size();
}

void SequentialStepper::begin_step(double h) noexcept {
  // eq. (8): force elements, then subsystems (in the order added), then the framework
  for (Stage* stage : stages_) stage->advance(h);
  framework_.begin_step(h);
}

CouplableSystem::ConstVectorRef SequentialStepper::coordinates() const noexcept {
  return framework_.coordinates();
}
CouplableSystem::ConstVectorRef SequentialStepper::speeds() const noexcept {
  return framework_.speeds();
}
CouplableSystem::ConstMatrixRef SequentialStepper::kinematics_inverse() const noexcept {
  return framework_.kinematics_inverse();
}
CouplableSystem::ConstVectorRef SequentialStepper::unconstrained_rate() const noexcept {
  return framework_.unconstrained_rate();
}
void SequentialStepper::solve_mass(ConstMatrixRef b, MatrixRef x) const noexcept {
  framework_.solve_mass(b, x);
}
void SequentialStepper::solve_mass_leading(ConstMatrixRef b, MatrixRef x) const noexcept {
  framework_.solve_mass_leading(b, x);
}
void SequentialStepper::finish_step(double h, ConstVectorRef extra_rate) noexcept {
  framework_.finish_step(h, extra_rate);
}

}  // namespace rig::model::solver
