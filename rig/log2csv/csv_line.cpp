#include "rig/log2csv/csv_line.h"

#include <cstdio>

namespace rig::log2csv {

void CsvLine::separate() {
  if (!first_) text_.push_back(',');
  first_ = false;
}

void CsvLine::add(double value) {
  separate();
  char buffer[32];
  const int n = std::snprintf(buffer, sizeof buffer, "%.17g", value);
  text_.append(buffer, static_cast<std::size_t>(n));
}

void CsvLine::add(std::int64_t value) {
  separate();
  text_.append(std::to_string(value));
}

void CsvLine::add(std::string_view text) {
  separate();
  if (text.find_first_of(",\"\n") == std::string_view::npos) {
    text_.append(text);
    return;
  }
  text_.push_back('"');
  for (char c : text) {
    if (c == '"') text_.push_back('"');
    text_.push_back(c);
  }
  text_.push_back('"');
}

std::string join_columns(const std::vector<std::string>& columns) {
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i != 0) out.push_back(',');
    out += columns[i];
  }
  return out;
}

}  // namespace rig::log2csv
