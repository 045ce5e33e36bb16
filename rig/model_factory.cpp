#include "rig/model_factory.h"

#include "model/combination/combination.h"
#include "model/paper/quarter_car_model.h"
#include "model/vehicle/vehicle_model.h"
#include "rig/driver/path_driver.h"
#include "rig/driver/table_driver.h"
#include "rig/thread_begin_step_runner.h"

namespace rig {
namespace {

/// A VehicleModel at step h, at rest or at the initial speed.
std::unique_ptr<model::SteppedModel> make_vehicle_model(
    const io::config::VehicleModelSettings& settings, const RigConfig& config) {
  const bool assist_input = config.routing.assist_from_input;
  const double step_s = config.rig.period_s;
  model::vehicle::VehicleParams params = settings.params;
  params.steering.assist_from_input = assist_input;
  params.fault_limits = config.rig.fault_limits;
  auto m = std::make_unique<model::vehicle::VehicleModel>(params, step_s);
  if (settings.initial_speed_mps != 0) m->set_forward_speed(settings.initial_speed_mps);
  return m;
}

/// A model::combination::Combination; its parallel option runs on the rig's worker thread.
std::unique_ptr<model::SteppedModel> make_combination_model(
    const io::config::CombinationModelSettings& settings, const RigConfig& config) {
  const bool assist_input = config.routing.assist_from_input;
  const double step_s = config.rig.period_s;
  model::combination::CombinationParams p;
  p.name = settings.name;
  p.units = settings.units;
  for (auto& unit : p.units) {
    unit.steering.assist_from_input = assist_input;
    unit.fault_limits = config.rig.fault_limits;
  }
  p.joints = settings.joints;
  p.parallel = settings.parallel;
  p.begin_step_runner = make_thread_begin_step_runner;
  p.newton = model::combination::default_combination_newton_params();
  auto m = std::make_unique<model::combination::Combination>(p, step_s);
  if (settings.initial_speed_mps != 0) m->set_forward_speed(settings.initial_speed_mps);
  return m;
}

}  // namespace

std::unique_ptr<model::SteppedModel> make_model(const RigConfig& config) {
  if (config.model.kind == "vehicle") {
    return make_vehicle_model(*config.model.vehicle, config);
  }
  if (config.model.kind == "combination") {
    return make_combination_model(*config.model.combination, config);
  }
  // kind is validated at load time; the rest is "quarter-car".
  return std::make_unique<model::paper::QuarterCarModel>(config.model.quarter_car,
                                                         config.rig.period_s);
}

std::unique_ptr<driver::Driver> make_driver(const RigConfig& config) {
  const io::InputSet& feeds = config.routing.driver_inputs;
  if (config.path_driver) return std::make_unique<driver::PathDriver>(*config.path_driver, feeds);
  if (config.driver) return std::make_unique<driver::TableDriver>(*config.driver, feeds);
  return nullptr;
}

}  // namespace rig
