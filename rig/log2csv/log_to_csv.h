#pragma once
/// @file
/// Converts an LCM event log (from the rig's --lcm-log or from lcm-logger) into one CSV file per
/// channel: OUTDIR/CHANNEL.csv, a header line, then one row per message.

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace rig::log2csv {

struct ChannelSummary {
  std::string file;       ///< the CSV written
  std::string type_name;  ///< decoder used ("raw" for unknown types)
  std::uint64_t rows = 0;
  std::uint64_t undecodable = 0;  ///< events that did not decode as the channel's type
};

struct ConversionSummary {
  std::uint64_t events = 0;
  std::map<std::string, ChannelSummary> channels;  ///< by channel name
};

/// The file name for a channel: characters other than letters, digits, '_', '-', '.' become '_'.
std::string csv_file_name(const std::string& channel);

/// Throws std::runtime_error if the log cannot be read or a CSV cannot be written.
ConversionSummary convert_lcm_log(const std::filesystem::path& log_file,
                                  const std::filesystem::path& out_dir);

}  // namespace rig::log2csv
