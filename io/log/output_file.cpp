#include "io/log/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>
#include <utility>

namespace rig::io::log {
namespace {

std::string prefix(const OutputPath& o) { return o.option + " " + o.path + ": "; }

/// A file's identity: device and inode if it exists, else its absolute, normalised path.
struct Identity {
  bool exists = false;
  dev_t dev = 0;
  ino_t ino = 0;
  std::filesystem::path path;
  bool operator==(const Identity& o) const {
    return exists == o.exists && (exists ? dev == o.dev && ino == o.ino : path == o.path);
  }
};

Identity identity(const std::filesystem::path& p) {
  Identity id;
  struct stat st {};
  if (::stat(p.c_str(), &st) == 0) {
    id.exists = true;
    id.dev = st.st_dev;
    id.ino = st.st_ino;
    return id;
  }
  std::error_code ec;
  id.path = std::filesystem::weakly_canonical(std::filesystem::absolute(p, ec), ec);
  if (ec) id.path = std::filesystem::absolute(p).lexically_normal();
  return id;
}

/// What is at the last component now: nothing or a regular file (false), a character device
/// (true), else an OutputFileError.
bool check_one(const OutputPath& o) {
  struct stat st {};
  if (::lstat(o.path.c_str(), &st) != 0) {
    if (errno != ENOENT) throw OutputFileError(prefix(o) + std::strerror(errno));
    std::filesystem::path parent = std::filesystem::path(o.path).parent_path();
    if (parent.empty()) parent = ".";
    struct stat dir {};
    if (::stat(parent.c_str(), &dir) != 0 || !S_ISDIR(dir.st_mode))
      throw OutputFileError(prefix(o) + "its folder " + parent.string() + " does not exist");
    if (::access(parent.c_str(), W_OK) != 0)
      throw OutputFileError(prefix(o) + "its folder is not writable: " + std::strerror(errno));
    return false;
  }
  if (S_ISLNK(st.st_mode))
    throw OutputFileError(prefix(o) + "is a symbolic link; refusing to follow it");
  if (S_ISDIR(st.st_mode)) throw OutputFileError(prefix(o) + "is a directory");
  if (!S_ISREG(st.st_mode) && !S_ISCHR(st.st_mode))
    throw OutputFileError(prefix(o) + "is neither a regular file nor a character device");
  return S_ISCHR(st.st_mode);
}

void rename_if_present(const std::string& from, const std::string& to, const OutputPath& o) {
  if (::rename(from.c_str(), to.c_str()) != 0 && errno != ENOENT)
    throw OutputFileError(prefix(o) + "cannot rename " + from + " to " + to + ": " +
                          std::strerror(errno));
}

/// NAME -> NAME.1 -> ... -> NAME.keep (the oldest removed); keep = 0: NAME removed.
void rotate(const OutputPath& o, int keep) {
  const std::string& p = o.path;
  if (keep == 0) {
    if (::unlink(p.c_str()) != 0 && errno != ENOENT)
      throw OutputFileError(prefix(o) + "cannot remove the old file: " + std::strerror(errno));
    return;
  }
  if (::unlink(rotated_name(p, keep).c_str()) != 0 && errno != ENOENT)
    throw OutputFileError(prefix(o) + "cannot remove " + rotated_name(p, keep) + ": " +
                          std::strerror(errno));
  for (int i = keep - 1; i >= 1; --i)
    rename_if_present(rotated_name(p, i), rotated_name(p, i + 1), o);
  rename_if_present(p, rotated_name(p, 1), o);
}

}  // namespace

std::string rotated_name(const std::string& path, int i) { return path + "." + std::to_string(i); }

void check_output_paths(const std::vector<OutputPath>& outputs,
                        const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::pair<const OutputPath*, Identity>> seen;
  for (const OutputPath& o : outputs) {
    if (o.path.empty() || check_one(o)) continue;  // a device (/dev/null) may be given twice
    const Identity id = identity(o.path);
    for (const auto& in : inputs) {
      if (identity(in) == id)
        throw OutputFileError(prefix(o) + "is an input of this run (" + in.string() +
                              "); refusing to overwrite it");
    }
    for (const auto& [other, other_id] : seen) {
      if (other_id == id)
        throw OutputFileError(prefix(o) + "the same file as " + other->option + " " + other->path +
                              "; give each output its own path");
    }
    seen.emplace_back(&o, id);
  }
}

int open_output_file(const OutputPath& o, int keep) {
  if (check_one(o)) {  // e.g. /dev/null
    const int fd = ::open(o.path.c_str(), O_WRONLY | O_CLOEXEC | O_NOFOLLOW | O_NOCTTY);
    if (fd < 0) throw OutputFileError(prefix(o) + std::strerror(errno));
    return fd;
  }
  rotate(o, keep);
  const int fd =
      ::open(o.path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY, 0644);
  if (fd < 0) throw OutputFileError(prefix(o) + "cannot create it: " + std::strerror(errno));
  return fd;
}

}  // namespace rig::io::log
