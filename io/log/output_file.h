#pragma once
/// @file
/// The one way a run opens its output files (overrun/event log, LCM log, summary JSON): checked
/// before the loop starts, never overwriting an earlier run's file, never following a symbolic
/// link at the last component.
///
/// An existing NAME is renamed NAME.1 first (NAME.1 to NAME.2, ..., at most `keep` kept, the
/// oldest removed; keep = 0 keeps none), so the path given is always the new run's file. NAME is
/// then created with O_CREAT | O_EXCL | O_NOFOLLOW. A character device (/dev/null) is opened as
/// it is. Load time only, never on the RT thread.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace rig::io::log {

/// An output path that cannot be used: bad usage (the rig exits 2), found before the loop.
class OutputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An output the user named: what it is (e.g. "--overrun-log") and its path ("" = none).
struct OutputPath {
  std::string option;
  std::string path;
};

/// Throws OutputFileError if two outputs name the same file, an output is one of `inputs` (the
/// configuration and the files it names), a symbolic link, a directory, or its folder does not
/// exist. Renames or creates nothing.
void check_output_paths(const std::vector<OutputPath>& outputs,
                        const std::vector<std::filesystem::path>& inputs);

/// Rotates an existing `path` (see above) and creates it; returns the open descriptor
/// (O_WRONLY | O_CLOEXEC). Throws OutputFileError naming `option`, the path and the reason.
int open_output_file(const OutputPath& output, int keep);

/// The rotated name: "NAME.i".
std::string rotated_name(const std::string& path, int i);

}  // namespace rig::io::log
