#pragma once
/// @file
/// Builds the model named by [model] kind. The executive only sees model::SteppedModel.

#include <memory>

#include "model/stepped_model.h"
#include "rig/config.h"

namespace rig {

std::unique_ptr<model::SteppedModel> make_model(const RigConfig& config);

}  // namespace rig
