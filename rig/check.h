#pragma once
/// @file
/// `rig check FILE...`: every kind of file a user hands the rig, recognised from its content and
/// checked completely (with the files it names), as `rig run` would load it. One registry of
/// kinds (file_kinds(), in check.cpp), each {name, what it looks like, recognizer, checker}: a
/// new kind of file (roads, sweeps) is one entry there.
///
/// Prints `FILE: KIND: OK`. A file of no kind: `FILE: not a rig file` and the kinds expected;
/// a bad file: `file:line: what is wrong`. Both exit 2.

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace rig {

/// A file as the recognizers see it.
struct FileContent {
  std::filesystem::path path;
  std::string head;                 ///< its first bytes (at most 64 KiB)
  std::optional<toml::table> toml;  ///< the whole file, if it is TOML
  std::string toml_error;           ///< else why not: `file:line: ...`
};

/// Reads what the recognizers look at; never throws for what is in the file.
FileContent read_file_content(const std::filesystem::path& file);

struct FileKind {
  std::string_view name;        ///< printed, and the value of --kind
  std::string_view looks_like;  ///< how it is recognised, for `not a rig file`
  bool (*recognize)(const FileContent& content);
  /// Loads and validates the whole file; throws io::config::ConfigError (`file:line: ...`).
  /// Remarks that are not errors go to `notes`.
  void (*check)(const FileContent& content, std::ostream& notes);
};

/// Every kind, in the order they are listed to the user.
std::span<const FileKind> file_kinds();

/// The kind named `name`, or nullptr.
const FileKind* find_file_kind(std::string_view name);

/// Checks one file as `kind` (nullptr: the kind its content shows). Writes `FILE: KIND: OK` and
/// notes to `out`, errors to `err`. Returns the exit code: 0 ok, 2 not a rig file or a bad one.
int check_file(const std::string& file, const FileKind* kind, std::ostream& out, std::ostream& err);

}  // namespace rig
