#include "io/can/bridge/can_settings.h"

#include "io/can/bridge/can_bridge.h"
#include "io/can/bridge/can_fallback_io.h"
#include "io/can/dbc/dbc_parser.h"

namespace rig::io::can::bridge {
namespace {

/// The first mapped message (RX or TX) that is a CAN FD frame, or nullptr.
const dbc::MessageDef* first_fd_message(const can::mapping::CanConfig& config) {
  for (const auto* list : {&config.mapping.rx, &config.mapping.tx}) {
    for (const auto& binding : *list) {
      const dbc::MessageDef& m = config.database.messages[binding.dbc_message];
      if (m.is_fd()) return &m;
    }
  }
  return nullptr;
}

}  // namespace

CanSettings read_can_settings(config::StrictTable& can_table,
                              std::shared_ptr<const signals::Catalogue> catalogue) {
  CanSettings s;
  s.catalogue = std::move(catalogue);
  s.interface = can_table.string("interface", "vcan0");
  if (s.interface.empty() || s.interface.size() > 15) {
    throw can_table.error("interface", "interface name must have 1..15 characters");
  }
  s.mapping_file = can_table.existing_path("mapping");
  if (can_table.has("dbc")) s.dbc_file = can_table.existing_path("dbc");
  s.fd = can_table.boolean("fd", true);
  s.kernel_filter = can_table.boolean("kernel_filter", false);
  if (!s.fd) {
    // A classic-only socket would drop every frame of an FD message without a word.
    if (const dbc::MessageDef* m = first_fd_message(load_can_files(s))) {
      throw can_table.error("fd", "false, but message " + m->name + " (" +
                                      std::to_string(m->length_bytes) + " bytes) of " +
                                      s.mapping_file.string() + " is a CAN FD frame");
    }
  }
  can_table.finish();
  return s;
}

can::mapping::CanConfig load_can_files(const CanSettings& settings) {
  can::mapping::CanConfig config;
  if (settings.dbc_file) {
    config.database = dbc::load_dbc(*settings.dbc_file);
    toml::table root = config::load_toml_file(settings.mapping_file);
    config::StrictTable table(root, settings.mapping_file, "mapping");
    (void)table.string("dbc", "");  // superseded by [can] dbc
    config.mapping =
        can::mapping::parse_can_mapping(table, config.database, settings.signal_catalogue());
    table.finish();
  } else {
    config = can::mapping::load_can_config(settings.mapping_file, settings.signal_catalogue());
  }
  return config;
}

std::unique_ptr<io::CycleIo> make_can_io(can::mapping::CanConfig config,
                                         const CanSettings& settings, const io::InputSet& feeds) {
  const dbc::MessageDef* fd_message = first_fd_message(config);
  const std::string fd_name = fd_message != nullptr ? fd_message->name : "";
  const std::uint32_t fd_bytes = fd_message != nullptr ? fd_message->length_bytes : 0;
  can::transport::TransportSettings transport;
  transport.interface = settings.interface;
  transport.fd = settings.fd;
  auto bridge = std::make_unique<CanBridge>(std::move(config), std::move(transport),
                                            settings.kernel_filter, feeds);
  if (!fd_name.empty() && !bridge->transport().fd_capable()) {
    throw config::ConfigError("CAN interface '" + settings.interface +
                              "' has a classic MTU (CAN FD off): message " + fd_name + " (" +
                              std::to_string(fd_bytes) + " bytes) of " +
                              settings.mapping_file.string() + " needs CAN FD (`ip link set " +
                              settings.interface + " mtu 72`, or map classic messages only)");
  }
  return bridge;
}

std::unique_ptr<io::CycleIo> make_can_io(const CanSettings& settings, const io::InputSet& feeds) {
  return make_can_io(load_can_files(settings), settings, feeds);
}

std::unique_ptr<io::CycleIo> make_can_fallback_io(const can::mapping::CanConfig& config,
                                                  const io::InputSet& feeds) {
  std::vector<CanFallbackIo::Fallback> fallbacks;
  for (const auto& message : config.mapping.rx) {
    for (const auto& s : message.signals) {
      if (s.model && feeds[s.model->slot]) fallbacks.push_back({s.model->slot, s.fallback});
    }
  }
  return std::make_unique<CanFallbackIo>(std::move(fallbacks));
}

}  // namespace rig::io::can::bridge
