#pragma once
/// @file
/// The data payload of an OpenCRG file, after the header's `$$` record: rows of one number per
/// channel ($KD_Definition), plain text (LRFI: 10-character reals, 8 per 80-character record;
/// LDFI: 20-character doubles, 4 per record; every row starts a new record; NaN is a field
/// starting with `*`) or binary (KRBI: 4-byte, KDBI: 8-byte IEEE big-endian numbers filling
/// 80-byte records one after the other, the last record padded with NaN). Internal to
/// io/config/crg_file.cpp; errors are ConfigError `file:line: what`.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "io/config/crg_header.h"

namespace rig::io::config::crg {

struct Payload {
  std::vector<double> values;  ///< rows * channels, row by row; NaN where the file has NaN
  std::size_t rows = 0;
  std::vector<int> row_line;  ///< text: the line of each row's first record; binary: empty
  int first_line = 0;         ///< the payload's first line (binary data: where errors point)
  /// `file:line` naming a row, for errors about its values.
  [[nodiscard]] std::string where(const std::string& file, std::size_t row) const;
};

/// Reads the payload of `channels` numbers per row. `rows`: the number of rows the header
/// expects (0: as many as there are).
Payload read_payload(std::string_view content, const Header& header, Format format,
                     std::size_t channels, std::size_t rows, const std::string& file);

}  // namespace rig::io::config::crg
