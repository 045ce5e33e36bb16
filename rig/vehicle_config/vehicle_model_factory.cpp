#include "model/vehicle/vehicle_model.h"
#include "rig/vehicle_config/vehicle_config.h"

namespace rig::vehicle_config {

std::unique_ptr<model::SteppedModel> make_vehicle_model(const VehicleModelSettings& settings,
                                                        double step_s) {
  auto m = std::make_unique<model::vehicle::VehicleModel>(settings.params, step_s);
  if (settings.initial_speed_mps != 0) m->set_forward_speed(settings.initial_speed_mps);
  return m;
}

}  // namespace rig::vehicle_config
