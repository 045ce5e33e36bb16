#include "rig/model_factory.h"

#include <cmath>
#include <iostream>

#include "model/combination/combination.h"
#include "model/paper/quarter_car_model.h"
#include "model/vehicle/vehicle_model.h"
#include "rig/driver/path_driver.h"
#include "rig/driver/table_driver.h"
#include "rig/thread_begin_step_runner.h"

namespace rig {
namespace {

/// The gear the run's driver asks for at t = 0 (99, automatic, without one).
int first_gear_request(const RigConfig& config) {
  model::Signals first{};
  if (auto d = make_driver(config)) d->update(0.0, first);
  const auto i = model::index(model::Signal::kGearRequest);
  if (!first.valid[i] || !std::isfinite(first.value[i])) return 99;
  return static_cast<int>(std::lround(first.value[i]));
}

/// Reports the throttle that holds the initial speed (a driver or ECU that wants the steady
/// state feeds it).
void report_equilibrium(double speed_mps, const model::vehicle::Equilibrium& e) {
  if (speed_mps == 0) return;
  std::cerr << "rig: initial speed " << speed_mps << " m/s: steady state in gear " << e.gear
            << ", throttle " << e.throttle << " holds it";
  if (std::abs(e.residual_ax_mps2) > 0.01)
    std::cerr << " (not quite: a_x " << e.residual_ax_mps2 << " m/s^2 left at that throttle)";
  std::cerr << "\n";
}

/// A VehicleModel at step h, in equilibrium at rest or at the initial speed.
std::unique_ptr<model::SteppedModel> make_vehicle_model(
    const io::config::VehicleModelSettings& settings, const RigConfig& config) {
  const bool assist_input = config.routing.assist_from_input;
  const double step_s = config.rig.period_s;
  model::vehicle::VehicleParams params = settings.params;
  params.steering.assist_from_input = assist_input;
  params.steering.angle_from_input = config.routing.angle_from_input;
  params.fault_limits = config.rig.fault_limits;
  auto m = std::make_unique<model::vehicle::VehicleModel>(params, step_s);
  const double v = settings.initial_speed_mps;
  report_equilibrium(v, m->settle(v, first_gear_request(config)));
  return m;
}

/// A model::combination::Combination, in equilibrium at rest or at the initial speed; its parallel
/// option runs on the rig's worker thread.
std::unique_ptr<model::SteppedModel> make_combination_model(
    const io::config::CombinationModelSettings& settings, const RigConfig& config) {
  const bool assist_input = config.routing.assist_from_input;
  const double step_s = config.rig.period_s;
  model::combination::CombinationParams p;
  p.name = settings.name;
  p.units = settings.units;
  for (auto& unit : p.units) {
    unit.steering.assist_from_input = assist_input;
    unit.steering.angle_from_input = config.routing.angle_from_input;
    unit.fault_limits = config.rig.fault_limits;
  }
  p.joints = settings.joints;
  p.parallel = settings.parallel;
  p.begin_step_runner = make_thread_begin_step_runner;
  p.newton = model::combination::default_combination_newton_params();
  auto m = std::make_unique<model::combination::Combination>(p, step_s);
  const double v = settings.initial_speed_mps;
  report_equilibrium(v, m->settle(v, first_gear_request(config)));
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
