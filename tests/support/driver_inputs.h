#pragma once
/// @file
/// Model inputs as a test driver sets them: every input valid and from the driver, gear
/// selection automatic (99), all values zero. Tests then set what their maneuver needs.

#include <cstddef>

#include "model/signals.h"

namespace rig::test {

inline model::Signals all_driver_inputs() {
  model::Signals s;
  for (std::size_t i = 0; i < model::index(model::kFirstOutput); ++i) {
    s.valid[i] = true;
    s.source[i] = model::SignalSource::kDriver;
  }
  s[model::Signal::kGearRequest] = 99;
  s[model::Signal::kIgnition] = 2;  // on (valid, so 0 would be off)  // automatic
  return s;
}

}  // namespace rig::test
