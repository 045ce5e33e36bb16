#include "rig/model_factory.h"

#include "model/examples/quarter_car/quarter_car_model.h"
#include "rig/driver/path_driver.h"
#include "rig/driver/table_driver.h"

namespace rig {

std::unique_ptr<model::SteppedModel> make_model(const RigConfig& config) {
  if (config.model.kind == "vehicle") {
    return vehicle_config::make_vehicle_model(*config.model.vehicle, config.rig.period_s);
  }
  if (config.model.kind == "combination") {
    return vehicle_config::make_combination_model(*config.model.combination, config.rig.period_s);
  }
  // kind is validated at load time; the rest is "quarter-car".
  return std::make_unique<model::examples::QuarterCarModel>(config.model.quarter_car,
                                                            config.rig.period_s);
}

std::unique_ptr<driver::Driver> make_driver(const RigConfig& config) {
  if (config.path_driver) return std::make_unique<driver::PathDriver>(*config.path_driver);
  if (config.driver) return std::make_unique<driver::TableDriver>(*config.driver);
  return nullptr;
}

}  // namespace rig
