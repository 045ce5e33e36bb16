#pragma once
/// @file
/// The combination files of config/combinations as CombinationParams, as the rig loads them
/// (io/config), for the combination tests.

#include <string>

#include "io/config/combination_file.h"
#include "io/config/strict_table.h"
#include "model/combination/combination_shell.h"

namespace rig::test {

inline constexpr const char* kCarTrailer = RIG_SOURCE_DIR "/config/combinations/car-trailer.toml";
inline constexpr const char* kTractorSemi =
    RIG_SOURCE_DIR "/config/combinations/tractor-semitrailer.toml";
inline constexpr const char* kTractorSemi40t =
    RIG_SOURCE_DIR "/config/combinations/tractor-semitrailer-40t.toml";
inline constexpr const char* kCarTowBarCar =
    RIG_SOURCE_DIR "/config/combinations/car-towbar-car.toml";

/// The [model] of a combination file (throws io::config::ConfigError with file:line).
inline model::combination::CombinationParams load_combination(const std::string& file) {
  const toml::table doc = io::config::load_toml_file(file);
  io::config::StrictTable top(doc, file, "top level");
  io::config::StrictTable m = top.table("model");
  (void)m.string("kind");
  const io::config::CombinationModelSettings s = io::config::read_combination_model(m);
  model::combination::CombinationParams p;
  p.name = s.name;
  p.units = s.units;
  p.joints = s.joints;
  p.parallel = s.parallel;
  p.newton = model::combination::default_combination_newton_params();
  return p;
}

}  // namespace rig::test
