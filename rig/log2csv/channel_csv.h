#pragma once
/// @file
/// Turns the events of one LCM channel into CSV rows. The first event of a channel picks the
/// decoder by the LCM type fingerprint (the first 8 bytes of every message): the rig's types
/// (rig.vehicle_state_t, rig.rig_status_t, rig.signals_t) are decoded field by field, anything
/// else gets the columns timestamp_us,channel,size_bytes.

#include <cstdint>
#include <memory>
#include <string>

#include "rig/log2csv/csv_line.h"

namespace rig::log2csv {

/// One LCM log event as this tool sees it.
struct Event {
  std::int64_t timestamp_us = 0;
  const std::string* channel = nullptr;
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
};

class ChannelCsv {
 public:
  virtual ~ChannelCsv() = default;
  /// The header line. Valid after the first successful row(); the array columns (unit0_..,
  /// wheel0_.., input_valid_<name>) are sized by the channel's first message.
  [[nodiscard]] virtual std::string header() const = 0;
  /// Fills `line` with the row of `event`; false if the event does not decode.
  virtual bool row(const Event& event, CsvLine& line) = 0;
  /// The LCM type this decoder reads ("raw" for unknown types).
  [[nodiscard]] virtual const char* type_name() const = 0;
};

/// The decoder for a channel whose first event is `first`.
std::unique_ptr<ChannelCsv> make_channel_csv(const Event& first);

}  // namespace rig::log2csv
