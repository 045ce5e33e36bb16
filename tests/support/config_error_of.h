#pragma once
/// @file
/// The message of the `io::config::ConfigError` a loader throws: the tests of strict readers
/// compare it with the `file:line: what is wrong` they expect.

#include <string>
#include <utility>

#include "io/config/config_error.h"

namespace rig::test {

/// What `f()` throws as a ConfigError; "" if it throws none (other exceptions pass through).
template <class F>
std::string config_error_of(F&& f) {
  try {
    std::forward<F>(f)();
  } catch (const io::config::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace rig::test
