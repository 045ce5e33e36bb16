#pragma once
/// @file
/// The [can] section of the rig configuration, and the factory the executive calls.
///
///     [can]
///     interface = "vcan0"                    # SocketCAN interface (--can overrides; "none" = off)
///     mapping = "can/steering-bench.toml"    # mapping file (relative to the config file)
///     dbc = "can/steering-bench.dbc"         # optional: overrides the mapping file's `dbc`
///     fd = true                              # optional: accept/send CAN FD frames (false with
///                                            #   an FD message mapped: error at `fd`)
///     kernel_filter = false                  # optional: CAN_RAW_FILTER on the RX message ids
///
/// kernel_filter = false (default) lets every frame through so unknown ids are counted
/// (unknown_frames); true spares the RT thread on a busy real bus, and unknown ids are then
/// dropped by the kernel without being counted.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "io/can/mapping/can_mapping.h"
#include "io/config/strict_table.h"
#include "io/cycle_io.h"

namespace rig::io::can::bridge {

struct CanSettings {
  std::string interface = "vcan0";
  std::filesystem::path mapping_file;
  std::optional<std::filesystem::path> dbc_file;  ///< overrides the mapping's `dbc` key
  bool fd = true;
  bool kernel_filter = false;
  /// The configured model's signal catalogue the mapping binds against (nullptr: the two-axle
  /// vehicle's, io/signals/catalogue.h).
  std::shared_ptr<const signals::Catalogue> catalogue;

  [[nodiscard]] const signals::Catalogue& signal_catalogue() const {
    return catalogue ? *catalogue : signals::Catalogue::two_axle_vehicle();
  }
};

/// Reads a [can] table (load time; config::ConfigError with file:line on bad input), its mapping
/// bound against `catalogue`. Calls finish().
CanSettings read_can_settings(config::StrictTable& can_table,
                              std::shared_ptr<const signals::Catalogue> catalogue = nullptr);

/// Loads the DBC and the mapping of `settings` (load time; config::ConfigError on bad input).
/// The DBC's notes (skipped sections) are in the result's database.warnings.
can::mapping::CanConfig load_can_files(const CanSettings& settings);

/// The bridge on loaded files: opens the transport; it writes the inputs in `feeds`.
std::unique_ptr<io::CycleIo> make_can_io(can::mapping::CanConfig config,
                                         const CanSettings& settings, const io::InputSet& feeds);

/// CAN switched off (`--can none`) on a configuration with [can]: writes each input in `feeds`
/// that the mapping receives as its `fallback`, flagged invalid, every cycle; sends nothing.
std::unique_ptr<io::CycleIo> make_can_fallback_io(const can::mapping::CanConfig& config,
                                                  const io::InputSet& feeds);

/// Loads DBC and mapping, opens the transport; the bridge writes the inputs in `feeds` (those
/// routed to CAN). Throws config::ConfigError (bad DBC/mapping; an FD message mapped on an
/// interface with the classic MTU) or can::transport::TransportError (no SocketCAN, unknown
/// interface), both with a clear message.
std::unique_ptr<io::CycleIo> make_can_io(const CanSettings& settings, const io::InputSet& feeds);

}  // namespace rig::io::can::bridge
