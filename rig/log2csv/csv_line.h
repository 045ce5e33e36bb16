#pragma once
/// @file
/// One CSV line built cell by cell. Doubles are written with 17 significant digits so that they
/// read back bit for bit.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rig::log2csv {

class CsvLine {
 public:
  /// Starts a new, empty line.
  void reset() {
    text_.clear();
    first_ = true;
  }
  void add(double value);
  void add(std::int64_t value);
  void add(std::string_view text);  ///< quoted if it holds a comma, quote or newline
  void add_empty() { separate(); }
  [[nodiscard]] const std::string& text() const { return text_; }

 private:
  void separate();
  std::string text_;
  bool first_ = true;
};

/// A header line: the column names separated by commas.
std::string join_columns(const std::vector<std::string>& columns);

}  // namespace rig::log2csv
