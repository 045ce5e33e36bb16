#include "model/solver/engine.h"

namespace rig::model::solver {

Engine::Engine(CouplableSystem& framework)
    : framework_(framework), zero_rate_(Eigen::VectorXd::Zero(framework.coordinate_size())) {}

void Engine::add_stage(Stage& stage) { stages_.push_back(&stage); }

void Engine::step(double h) noexcept {
  begin_step(h);
  framework_.finish_step(h, zero_rate_);
}

Eigen::Index Engine::coordinate_size() const noexcept { return framework_.coordinate_size(); }

void Engine::begin_step(double h) noexcept {
  // eq. (8): force elements, then subsystems (in the order added), then the framework
  for (Stage* stage : stages_) stage->advance(h);
  framework_.begin_step(h);
}

CouplableSystem::ConstVectorRef Engine::coordinates() const noexcept {
  return framework_.coordinates();
}
CouplableSystem::ConstVectorRef Engine::speeds() const noexcept { return framework_.speeds(); }
CouplableSystem::ConstMatrixRef Engine::kinematics_inverse() const noexcept {
  return framework_.kinematics_inverse();
}
CouplableSystem::ConstVectorRef Engine::unconstrained_rate() const noexcept {
  return framework_.unconstrained_rate();
}
void Engine::solve_mass(ConstMatrixRef b, MatrixRef x) const noexcept {
  framework_.solve_mass(b, x);
}
void Engine::solve_mass_leading(ConstMatrixRef b, MatrixRef x) const noexcept {
  framework_.solve_mass_leading(b, x);
}
void Engine::finish_step(double h, ConstVectorRef extra_rate) noexcept {
  framework_.finish_step(h, extra_rate);
}

}  // namespace rig::model::solver
