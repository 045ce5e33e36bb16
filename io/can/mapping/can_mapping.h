#pragma once
/// @file
/// Which DBC signals bind to which model signals, per direction, read from TOML (load time).
///
/// File format (see config/can/steering-bench.toml for a complete example):
///
///     dbc = "steering-bench.dbc"        # relative to this file
///
///     [[rx]]                            # a message the rig receives
///     message = "EPS_Status"            # BO_ name in the DBC
///     timeout_ms = 30                   # optional; default 3 x GenMsgCycleTime
///     counter = { signal = "EPS_AliveCounter", modulus = 16, max_step = 1 }     # optional
///                                       # (+ unlatch_steps = 1: see below)
///     checksum = { signal = "EPS_Checksum", type = "crc8_sae_j1850", bytes = [1, 2, 3] }  # opt.
///     # or a generic CRC (width 8/16/32; `signal`, or `position` = first byte, MSB first):
///     # checksum = { type = "crc", width, poly, init, refin, refout, xorout, bytes, position }
///     # or, instead of counter and checksum, AUTOSAR E2E (docs/e2e.md):
///     # e2e = { profile = "P01" | "P02" | "P04" | "P05", data_id, data_id_mode, data_id_list,
///     #         crc_offset_bits, counter_offset_bits, max_delta_counter }
///     [[rx.signal]]
///     dbc = "EPS_MotorTorque"           # SG_ name in that message
///     model = "assist_torque_nm"        # a signal catalogue name or alias (io/signals)
///     convert = "none"                  # optional named conversion, or scale/offset:
///     scale = 1.0                       #   model = dbc * scale + offset
///     offset = 0.0
///     fallback = 0.0                    # model value applied (and flagged invalid) on timeout
///
///     [[tx]]                            # a message the rig sends at its GenMsgCycleTime
///     message = "RIG_Steering"
///     counter = ...; checksum = ...     # as above, filled in on every send
///     [[tx.signal]]
///     dbc = "SteeringWheelAngle"; model = "steering_wheel_angle_rad"; convert = "deg_to_rad"
///     [[tx.signal]]
///     dbc = "RIG_Mode"; constant = 1.0  # a fixed physical value instead of a model signal
///     [[tx.signal]]
///     dbc = "VehicleSpeed"; model = "vehicle_speed_mps"; invalid = 0xFFFF   # optional
///
///     [[restbus]]                       # every cyclic message a DBC node sends (restbus.h)
///     node = "GW"; set = { GW_Ignition = 2, GW_Speed = "vehicle_speed_mps" }
///
/// TX `invalid` (optional, an integer raw value that fits the signal's bits, e.g. the DBC's SNA
/// value) is sent, unclamped, while the model signal is flagged invalid (a timed-out input, or
/// every model output after a vehicle fault held by [rig] on_vehicle_fault = "hold"); without
/// it the signal's value is sent as it is, i.e. the model's last valid output.
///
/// Named conversions (model = dbc * scale): "none", "deg_to_rad", "kph_to_mps", "bar_to_pa",
/// "rpm_to_radps", "percent_to_ratio". TX uses the inverse: dbc = (model - offset) / scale.
/// Unmapped TX signals are sent at their GenSigStartValue. Checksum `bytes` default to every
/// byte of the message except those of the checksum; the checksum signal must be 8 bits (for
/// type "crc": `width` bits). `counter`, `checksum` and `e2e` are read by read_protection
/// (protection_config.h); E2E keys, defaults and counters: docs/e2e.md.
/// Given, each byte at most once (so at most the message's length, 64 at most for CAN FD).
/// The alive counter must advance by 1..max_step (mod modulus) per frame; a repeated (frozen) or
/// jumping counter is a failure that latches the message: its frames are rejected until the
/// counter has advanced properly `unlatch_steps` times in a row (default 1), also across a
/// timeout (sequence_checker.h). Every name is checked against the DBC and the signal catalogue
/// (RX binds inputs only, TX any entry; an unknown name lists the closest ones), and
/// every error is config::ConfigError("file:line: ..."). Contradictions are errors too: counter and
/// checksum sharing bits, a checksum byte listed twice, `convert` with `scale`, `model` with
/// `constant`, one message both received and sent.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/can/dbc/dbc_database.h"
#include "io/can/e2e/crc.h"
#include "io/can/e2e/e2e_profile.h"
#include "io/can/mapping/checksum.h"
#include "io/config/strict_table.h"
#include "io/signals/catalogue.h"
#include "model/signals.h"

namespace rig::io::can::mapping {

/// One bound signal: index into MessageDef::signals, and the model side.
struct SignalBinding {
  std::size_t dbc_signal = 0;             ///< index in MessageDef::signals
  std::optional<signals::Binding> model;  ///< the catalogue entry; empty for a TX constant
  double scale = 1.0;                     ///< model = dbc * scale + offset
  double offset = 0.0;
  double fallback = 0.0;                       ///< RX: model value on timeout
  double constant = 0.0;                       ///< TX without model signal: physical DBC value sent
  std::optional<std::uint64_t> invalid_raw{};  ///< TX: raw value sent while `model` is invalid
};

struct CounterSpec {
  std::size_t dbc_signal = 0;
  std::uint32_t modulus = 16;
  std::uint32_t max_step = 1;       ///< RX: accepted advance per frame is 1..max_step
  std::uint32_t unlatch_steps = 1;  ///< RX: proper steps in a row that end a counter failure
};

struct ChecksumSpec {
  std::size_t dbc_signal = 0;  ///< the signal holding the checksum (unless `position`)
  ChecksumType type = ChecksumType::kCrc8SaeJ1850;
  std::vector<std::uint8_t> bytes;  ///< covered byte indices, in order
  e2e::Crc crc{};                   ///< kCrc8SaeJ1850 (its preset) and kCrc
  /// `position`: the CRC's first byte; width / 8 bytes, most significant first (no DBC signal).
  std::optional<std::uint32_t> position_byte{};
};

/// One mapped message (either direction).
struct MessageBinding {
  std::size_t dbc_message = 0;  ///< index in Database::messages
  std::vector<SignalBinding> signals;
  std::optional<CounterSpec> counter;
  std::optional<ChecksumSpec> checksum;
  std::optional<e2e::E2eSpec> e2e;  ///< AUTOSAR E2E (docs/e2e.md); excludes counter and checksum
  std::int64_t timeout_ns = 0;      ///< RX only
  std::int64_t period_ns = 0;       ///< TX only (GenMsgCycleTime), > 0
};

struct CanMapping {
  std::vector<MessageBinding> rx;
  std::vector<MessageBinding> tx;  ///< [[tx]], then the messages [[restbus]] expands into
  /// `file:line: ...` notes (restbus messages not sent). Never printed here; the caller decides.
  std::vector<std::string> warnings;
};

/// The DBC and the mapping that refers to it.
struct CanConfig {
  dbc::Database database;
  CanMapping mapping;
};

/// Reads the mapping tables `rx`, `tx` and `restbus` from `table` against `database`, binding
/// `model` names through `catalogue` (does not read the `dbc` key and does not call finish() on
/// `table`).
CanMapping parse_can_mapping(
    config::StrictTable& table, const dbc::Database& database,
    const signals::Catalogue& catalogue = signals::Catalogue::two_axle_vehicle());

/// Reads a mapping TOML file: its `dbc` key (relative path) is loaded with load_dbc.
CanConfig load_can_config(
    const std::filesystem::path& toml_file,
    const signals::Catalogue& catalogue = signals::Catalogue::two_axle_vehicle());
/// The DBC a mapping file names (its `dbc` key, resolved relative to the file), without loading
/// either: what the rig reads, so that no output may overwrite it.
std::filesystem::path mapping_dbc_path(const std::filesystem::path& toml_file);

}  // namespace rig::io::can::mapping
