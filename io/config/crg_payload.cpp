#include "io/config/crg_payload.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rig::io::config::crg {
namespace {

constexpr std::size_t kBinaryRecordBytes = 80;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string_view rtrim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())) != 0) s.remove_suffix(1);
  return s;
}

struct TextLine {
  std::string_view text;
  int line = 0;
};

/// The payload's records, trailing blank lines dropped.
std::vector<TextLine> text_records(std::string_view content, const Header& h) {
  std::vector<TextLine> lines;
  int line = h.payload_line;
  std::size_t pos = h.payload_offset;
  while (pos < content.size()) {
    std::size_t end = content.find('\n', pos);
    if (end == std::string_view::npos) end = content.size();
    lines.push_back({rtrim(content.substr(pos, end - pos)), line++});
    pos = end + 1;
  }
  while (!lines.empty() && lines.back().text.empty()) lines.pop_back();
  return lines;
}

/// One record's fixed-width fields into `out`.
void read_fields(const TextLine& r, std::size_t width, std::size_t expected,
                 const std::string& file, std::vector<double>& out) {
  const std::size_t count = (r.text.size() + width - 1) / width;
  if (count != expected)
    throw error_at(file, r.line,
                   std::to_string(count) + " numbers of " + std::to_string(width) +
                       " characters, expected " + std::to_string(expected) +
                       " (the channels of $KD_Definition, each row starting a new record)");
  for (std::size_t f = 0; f < count; ++f) {
    const std::string_view field = r.text.substr(f * width, width);
    std::size_t lead = 0;
    while (lead < field.size() && field[lead] == ' ') ++lead;
    if (lead < field.size() && field[lead] == '*') {  // a NaN placeholder (*missing*, **unused**)
      out.push_back(kNaN);
      continue;
    }
    const auto value = parse_number(field);
    if (!value)
      throw error_at(file, r.line,
                     "characters " + std::to_string(f * width + 1) + "-" +
                         std::to_string(f * width + field.size()) + " ('" + std::string(field) +
                         "') are not a finite number");
    out.push_back(*value);
  }
}

Payload text_payload(std::string_view content, const Header& h, std::size_t width,
                     std::size_t channels, const std::string& file) {
  const std::size_t per_record = 80 / width;
  const std::size_t records_per_row = (channels + per_record - 1) / per_record;
  const std::vector<TextLine> records = text_records(content, h);
  Payload p;
  p.first_line = h.payload_line;
  if (records.size() % records_per_row != 0)
    throw error_at(file, records.back().line,
                   "the data ends inside a row: " + std::to_string(records.size()) +
                       " records, and a row of " + std::to_string(channels) + " channels takes " +
                       std::to_string(records_per_row));
  p.rows = records.size() / records_per_row;
  p.values.reserve(p.rows * channels);
  for (std::size_t r = 0; r < records.size(); ++r) {
    const std::size_t within = r % records_per_row;
    if (within == 0) p.row_line.push_back(records[r].line);
    const std::size_t expected = std::min(per_record, channels - within * per_record);
    read_fields(records[r], width, expected, file, p.values);
  }
  return p;
}

double big_endian(const unsigned char* b, std::size_t width) {
  std::uint64_t bits = 0;
  for (std::size_t i = 0; i < width; ++i) bits = (bits << 8) | b[i];
  if (width == 4)
    return static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(bits)));
  return std::bit_cast<double>(bits);
}

Payload binary_payload(std::string_view content, const Header& h, std::size_t width,
                       std::size_t channels, std::size_t rows, const std::string& file) {
  Payload p;
  p.first_line = h.payload_line;
  const std::size_t bytes = content.size() - h.payload_offset;
  if (bytes % kBinaryRecordBytes != 0)
    throw error_at(file, h.payload_line,
                   "the binary data is " + std::to_string(bytes) +
                       " bytes, not whole 80-byte records (" +
                       std::to_string(bytes / kBinaryRecordBytes) + " records and " +
                       std::to_string(bytes % kBinaryRecordBytes) +
                       " bytes): the file is damaged (a copy as text, turning CR LF into LF, "
                       "loses bytes)");
  const std::size_t count = bytes / width;
  const auto* data = reinterpret_cast<const unsigned char*>(content.data() + h.payload_offset);
  p.values.resize(count);
  for (std::size_t i = 0; i < count; ++i) p.values[i] = big_endian(data + i * width, width);
  const std::size_t per_record = kBinaryRecordBytes / width;
  p.rows = rows > 0 ? rows : count / channels;
  // without a row count: trailing rows of padding NaN are no rows
  while (rows == 0 && p.rows > 0 && count - (p.rows - 1) * channels < per_record &&
         std::all_of(p.values.begin() + static_cast<std::ptrdiff_t>((p.rows - 1) * channels),
                     p.values.begin() + static_cast<std::ptrdiff_t>(p.rows * channels),
                     [](double v) { return std::isnan(v); }))
    --p.rows;
  const std::size_t used = p.rows * channels;
  if (used > count || count - used >= per_record ||
      !std::all_of(p.values.begin() + static_cast<std::ptrdiff_t>(used), p.values.end(),
                   [](double v) { return std::isnan(v); }))
    throw error_at(file, h.payload_line,
                   std::to_string(count) + " numbers in the binary data, not " +
                       std::to_string(p.rows) + " rows of " + std::to_string(channels) +
                       " channels and at most one record's NaN padding");
  p.values.resize(used);
  return p;
}

}  // namespace

std::string Payload::where(const std::string& file, std::size_t row) const {
  if (row < row_line.size()) return file + ":" + std::to_string(row_line[row]);
  return file + ":" + std::to_string(first_line) + ": row " + std::to_string(row + 1) +
         " of the binary data";
}

Payload read_payload(std::string_view content, const Header& header, Format format,
                     std::size_t channels, std::size_t rows, const std::string& file) {
  if (!header.has_payload || header.payload_offset >= content.size())
    throw error_at(file, header.has_payload ? header.payload_line : 1,
                   "no road data: the header's $$$$ record and the rows after it are missing");
  switch (format) {
    case Format::kLrfi:
      return text_payload(content, header, 10, channels, file);
    case Format::kLdfi:
      return text_payload(content, header, 20, channels, file);
    case Format::kKrbi:
      return binary_payload(content, header, 4, channels, rows, file);
    case Format::kKdbi:
      break;
  }
  return binary_payload(content, header, 8, channels, rows, file);
}

}  // namespace rig::io::config::crg
