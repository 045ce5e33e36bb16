#pragma once
/// @file
/// Thrown when the transport cannot be set up at load time (no AF_CAN in the kernel, unknown
/// interface, ...). Never thrown on the RT path.

#include <stdexcept>
#include <string>

namespace rig::io::can::transport {

class TransportError : public std::runtime_error {
 public:
  explicit TransportError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace rig::io::can::transport
