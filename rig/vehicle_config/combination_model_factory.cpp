#include "model/combination/combination.h"
#include "rig/vehicle_config/thread_begin_step_runner.h"
#include "rig/vehicle_config/vehicle_config.h"

namespace rig::vehicle_config {

std::unique_ptr<model::SteppedModel> make_combination_model(
    const CombinationModelSettings& settings, double step_s) {
  model::combination::CombinationParams p;
  p.name = settings.name;
  p.units = settings.units;
  p.joints = settings.joints;
  p.parallel = settings.parallel;
  p.begin_step_runner = make_thread_begin_step_runner;
  p.newton = model::combination::default_combination_newton_params();
  auto m = std::make_unique<model::combination::Combination>(p, step_s);
  if (settings.initial_speed_mps != 0) m->set_forward_speed(settings.initial_speed_mps);
  return m;
}

}  // namespace rig::vehicle_config
