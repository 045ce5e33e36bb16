#pragma once
/// @file
/// Builds the model named by [model] kind and the driver of [driver], each handed its part of
/// the routing (config.routing: the assist choice, the driver's inputs). The executive only sees
/// model::SteppedModel and driver::Driver.

#include <memory>

#include "model/stepped_model.h"
#include "rig/config.h"
#include "rig/driver/driver.h"

namespace rig {

std::unique_ptr<model::SteppedModel> make_model(const RigConfig& config);

/// The [driver]: a TableDriver (kind = "table"), a PathDriver (kind = "path"), or nullptr.
std::unique_ptr<driver::Driver> make_driver(const RigConfig& config);

}  // namespace rig
