#pragma once
/// @file
/// The one way the rig reads a file (configurations, vehicles, combinations, CAN mappings, DBCs,
/// `rig check`): it must be a regular file of bounded size. A device would be read until memory
/// runs out (/dev/zero), a FIFO would block forever, a directory would read as empty.

#include <cstddef>
#include <filesystem>
#include <string>

namespace rig::io::config {

/// Larger than any configuration or DBC the rig has a use for.
inline constexpr std::size_t kMaxInputFileBytes = 16u << 20;  // 16 MiB

/// The whole content of `file`. Throws ConfigError("FILE:1: cannot read file ...") if it is
/// missing, not a regular file (named: a directory, a FIFO, a character device, ...) or larger
/// than `max_bytes`. Never blocks on a FIFO (opened with O_NONBLOCK, then refused).
std::string read_input_file(const std::filesystem::path& file,
                            std::size_t max_bytes = kMaxInputFileBytes);

}  // namespace rig::io::config
