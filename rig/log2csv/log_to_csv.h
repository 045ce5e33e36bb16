#pragma once
/// @file
/// Converts an LCM event log (from the rig's --lcm-log or from lcm-logger) into one CSV file per
/// channel: OUTDIR/CHANNEL.csv, a header line, then one row per message.

#include <cstdint>
#include <filesystem>
#include <map>
#include <stdexcept>
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

/// A CSV could not be written completely (a full disk, an I/O error): rig-log2csv exits 3.
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws std::runtime_error if the log cannot be read, WriteError if a CSV cannot be written
/// completely (every write is checked, including the last flush; the temporary files removed).
ConversionSummary convert_lcm_log(const std::filesystem::path& log_file,
                                  const std::filesystem::path& out_dir);

}  // namespace rig::log2csv
