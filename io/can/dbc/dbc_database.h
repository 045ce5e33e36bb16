#pragma once
/// @file
/// The parsed contents of a DBC file: plain data, built once at load time. The per-frame path
/// never touches these strings; it uses the precompiled plans of signal_codec.h.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rig::io::can::dbc {

/// `@1` = Intel (little endian, start bit = LSB); `@0` = Motorola (big endian, start bit = MSB
/// in the DBC "sawtooth" numbering: bit 7 of byte 0 is 7, bit 0 of byte 1 is 8).
enum class ByteOrder : std::uint8_t { kIntel, kMotorola };

/// SIG_VALTYPE_: 0 (default) integer, 1 IEEE float32 (length 32), 2 IEEE double (length 64).
enum class ValueType : std::uint8_t { kInteger, kFloat32, kFloat64 };

/// `M` = the multiplexor switch of its message, `mN` = present only when the switch is N.
enum class MuxRole : std::uint8_t { kNone, kMultiplexor, kMultiplexed };

/// One VAL_ entry: raw value -> text.
struct ValueDescription {
  std::int64_t value = 0;
  std::string text;
};

/// One SG_ line plus what CM_, VAL_, BA_ and SIG_VALTYPE_ add to it.
struct SignalDef {
  std::string name;
  int line = 0;  ///< line of the SG_ in the file, for messages
  std::uint32_t start_bit = 0;
  std::uint32_t length_bits = 1;  ///< 1..64
  ByteOrder byte_order = ByteOrder::kIntel;
  bool is_signed = false;  ///< `-` in the DBC
  ValueType value_type = ValueType::kInteger;
  double factor = 1.0;  ///< physical = raw * factor + offset
  double offset = 0.0;
  double minimum = 0.0;  ///< physical range; minimum == maximum == 0 means "no range given"
  double maximum = 0.0;
  std::string unit;
  std::vector<std::string> receivers;
  MuxRole mux_role = MuxRole::kNone;
  std::uint32_t mux_value = 0;  ///< for kMultiplexed: the switch value of its page
  std::string comment;
  std::vector<ValueDescription> value_descriptions;
  /// GenSigStartValue as a RAW value (Vector convention), BA_DEF_DEF_ default or 0.
  double start_value_raw = 0.0;

  /// True when the DBC gives a usable [minimum, maximum] (not both zero, minimum < maximum).
  [[nodiscard]] bool has_range() const { return minimum < maximum; }
};

/// One BO_ block.
struct MessageDef {
  std::uint32_t id = 0;   ///< identifier without the extended flag (bit 31 of the DBC id)
  bool extended = false;  ///< 29-bit identifier (bit 31 set in the DBC's BO_ id)
  std::string name;
  std::uint32_t length_bytes = 0;  ///< DLC in bytes, 0..64 (more than 8 = CAN FD)
  std::string sender;
  std::vector<SignalDef> signals;
  std::string comment;
  /// GenMsgCycleTime [ms] (BA_ or the BA_DEF_DEF_ default); 0 = not cyclic / unknown.
  std::uint32_t cycle_time_ms = 0;
  int line = 0;

  bool fd_format = false;  ///< BA_ "VFrameFormat" StandardCAN_FD / ExtendedCAN_FD

  /// A CAN FD frame: longer than 8 bytes, or so declared by VFrameFormat.
  [[nodiscard]] bool is_fd() const { return length_bytes > 8 || fd_format; }
  /// The DBC's own id: with bit 31 set for extended ids.
  [[nodiscard]] std::uint32_t dbc_id() const { return extended ? (id | 0x80000000u) : id; }
  [[nodiscard]] const SignalDef* find_signal(std::string_view signal_name) const;
};

/// One BA_DEF_ (attribute definition) with its BA_DEF_DEF_ default, kept as text.
struct AttributeDefinition {
  std::string object_type;  ///< "", "BU_", "BO_", "SG_", "EV_"
  std::string name;
  std::string value_type;     ///< "INT", "HEX", "FLOAT", "STRING", "ENUM"
  std::string default_value;  ///< from BA_DEF_DEF_, "" if none
};

/// A whole DBC file.
struct Database {
  std::string file;  ///< name used in messages
  std::string version;
  std::vector<std::string> nodes;  ///< BU_
  std::vector<MessageDef> messages;
  std::vector<AttributeDefinition> attribute_definitions;
  /// `file:line: ...` notes about skipped (unknown or unsupported) sections. Never printed by
  /// the library; the caller decides.
  std::vector<std::string> warnings;

  [[nodiscard]] const MessageDef* find_message(std::string_view message_name) const;
  [[nodiscard]] const MessageDef* find_message(std::uint32_t id, bool extended) const;
};

}  // namespace rig::io::can::dbc
