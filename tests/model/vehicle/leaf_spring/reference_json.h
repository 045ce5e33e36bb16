#pragma once
/// @file
/// Reads the flat JSON object that leaf_fe_reference.py writes: each key holds a number or a
/// list of numbers. Enough of JSON for that file, for the tests only.

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rig::test {

class FlatJson {
 public:
  explicit FlatJson(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::stringstream ss;
    ss << in.rdbuf();
    text_ = ss.str();
  }

  /// The numbers at `key` (one for a plain number).
  [[nodiscard]] std::vector<double> numbers(const std::string& key) const {
    const std::string quoted = "\"" + key + "\":";
    const std::size_t at = text_.find(quoted);
    if (at == std::string::npos) throw std::runtime_error("no key " + key);
    const char* p = text_.c_str() + at + quoted.size();
    while (*p == ' ' || *p == '\n') ++p;
    std::vector<double> out;
    const bool list = *p == '[';
    if (list) ++p;
    for (;;) {
      while (*p == ' ' || *p == '\n' || *p == ',') ++p;
      if (*p == ']' || *p == '\0') break;
      char* end = nullptr;
      out.push_back(std::strtod(p, &end));
      if (end == p) throw std::runtime_error("not a number at " + key);
      p = end;
      if (!list) break;
    }
    return out;
  }
  [[nodiscard]] double number(const std::string& key) const { return numbers(key).at(0); }

 private:
  std::string text_;
};

}  // namespace rig::test
