#include "rig/model_factory.h"

#include "model/examples/quarter_car/quarter_car_model.h"

namespace rig {

std::unique_ptr<model::SteppedModel> make_model(const RigConfig& config) {
  if (config.model.kind == "vehicle") {
    return vehicle_config::make_vehicle_model(*config.model.vehicle, config.rig.period_s);
  }
  // kind is validated at load time; "quarter-car" is the only one so far.
  return std::make_unique<model::examples::QuarterCarModel>(config.model.quarter_car,
                                                            config.rig.period_s);
}

}  // namespace rig
