#pragma once
/// @file
/// Strict reading of TOML configuration: every key must be consumed, every value checked, and
/// every error names `file:line`. Load time only; never used on the RT thread.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "io/config/config_error.h"

namespace rig::io::config {

/// Parses a TOML file. Throws ConfigError("file:line: ...") if it is missing or malformed.
toml::table load_toml_file(const std::filesystem::path& file);

/// The most entries any list of a configuration may have (each list has its own, smaller bound
/// where the rig has one: checksum bytes, axles, units, ...): a list is never unbounded.
inline constexpr std::size_t kMaxListEntries = 1'000'000;

/// A view of one TOML table that remembers which keys were read, so that finish() can reject
/// unknown ones. Numbers accept integers and floats alike.
class StrictTable {
 public:
  /// `context` names the table in messages, e.g. "[rig]".
  StrictTable(const toml::table& table, std::filesystem::path file, std::string context);

  [[nodiscard]] bool has(std::string_view key) const;

  [[nodiscard]] double number(std::string_view key);
  [[nodiscard]] double number(std::string_view key, double fallback);
  /// A number that must lie in [min, max].
  [[nodiscard]] double number_in(std::string_view key, double min, double max);
  [[nodiscard]] double number_in(std::string_view key, double fallback, double min, double max);
  [[nodiscard]] long long integer(std::string_view key);
  [[nodiscard]] long long integer(std::string_view key, long long fallback);
  /// An integer that must lie in [min, max]. Every integer key is read so: a float (`80.7`, also
  /// `80.0`) is an error, never truncated.
  [[nodiscard]] long long integer_in(std::string_view key, long long min, long long max);
  [[nodiscard]] long long integer_in(std::string_view key, long long fallback, long long min,
                                     long long max);
  [[nodiscard]] bool boolean(std::string_view key, bool fallback);
  [[nodiscard]] std::string string(std::string_view key);
  [[nodiscard]] std::string string(std::string_view key, std::string_view fallback);
  /// A string that must be one of `allowed`.
  [[nodiscard]] std::string choice(std::string_view key, std::string_view fallback,
                                   const std::vector<std::string_view>& allowed);
  /// A path string, resolved relative to the directory of this file. Must exist.
  [[nodiscard]] std::filesystem::path existing_path(std::string_view key);
  /// The list readers: more than `max_entries` entries is an error at the key (file:line),
  /// found before any entry is read.
  [[nodiscard]] std::vector<double> numbers(std::string_view key,
                                            std::size_t max_entries = kMaxListEntries);
  /// An array of integers (a float element is an error, as for integer_in).
  [[nodiscard]] std::vector<long long> integers(std::string_view key,
                                                std::size_t max_entries = kMaxListEntries);
  /// An array of strings, each with its node (for errors at the element's line).
  [[nodiscard]] std::vector<std::pair<std::string, const toml::node*>> strings(
      std::string_view key, std::size_t max_entries = kMaxListEntries);
  /// An array of rows of `columns` numbers each, e.g. [[x, y, z], ...].
  [[nodiscard]] std::vector<std::vector<double>> number_rows(
      std::string_view key, std::size_t columns, std::size_t max_entries = kMaxListEntries);
  /// Array of tables, e.g. [[axle]].
  [[nodiscard]] std::vector<StrictTable> tables(std::string_view key,
                                                std::size_t max_entries = kMaxListEntries);
  /// Throws if the array at `key` has more than `max_entries` entries.
  void check_length(std::string_view key, const toml::array& array, std::size_t max_entries) const;

  /// The raw node at a required key, marked as read (for values of more than one shape).
  [[nodiscard]] const toml::node& node(std::string_view key) { return require(key); }

  [[nodiscard]] StrictTable table(std::string_view key);
  [[nodiscard]] std::optional<StrictTable> optional_table(std::string_view key);

  /// Throws on the first key that was never read.
  void finish() const;

  /// An error located at `key` (or at the table itself if the key is absent).
  [[nodiscard]] ConfigError error(std::string_view key, std::string_view what) const;
  /// An error located at the table.
  [[nodiscard]] ConfigError error(std::string_view what) const;
  /// An error located at `node` (an element of one of this table's arrays, e.g. a row).
  [[nodiscard]] ConfigError error_at(const toml::node& node, std::string_view key,
                                     std::string_view what) const;

  /// `file:line` of `key` (of the table if the key is absent), for messages raised later.
  [[nodiscard]] std::string location(std::string_view key) const;
  /// `file:line` of `node` (an entry of this table or of a table nested in it).
  [[nodiscard]] std::string location(const toml::node& node) const { return where(node.source()); }

  [[nodiscard]] const std::filesystem::path& file() const { return file_; }
  [[nodiscard]] const std::string& context() const { return context_; }
  [[nodiscard]] const toml::table& raw() const { return *table_; }

 private:
  const toml::node& require(std::string_view key);
  [[nodiscard]] std::string where(const toml::source_region& region) const;

  const toml::table* table_;
  std::filesystem::path file_;
  std::string context_;
  std::vector<std::string> used_;
};

}  // namespace rig::io::config
