#pragma once
/// @file
/// The one exception type for bad configuration: its message is `file:line: what is wrong`.

#include <stdexcept>
#include <string>

namespace rig::io::config {

class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rig::io::config
