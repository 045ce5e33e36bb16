#include "io/config/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/config/config_error.h"

namespace rig::io::config {
namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

/// Closes the descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_input_file(const std::filesystem::path& file, std::size_t max_bytes) {
  const std::string name = file.string();
  const std::string where = name + ":1: cannot read file";
  // O_NONBLOCK: opening a FIFO must not wait for a writer; the fstat below refuses it.
  const Fd f{::open(name.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY)};
  if (f.fd < 0) {
    if (errno == ENOENT) throw ConfigError(where + " (missing or not a regular file)");
    throw ConfigError(where + ": " + std::strerror(errno));
  }
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) throw ConfigError(where + ": " + std::strerror(errno));
  if (!S_ISREG(st.st_mode))
    throw ConfigError(where + ": it is " + kind_of(st.st_mode) + ", not a regular file");
  const auto too_large = [&] {
    const bool mib = max_bytes % (std::size_t{1} << 20) == 0;
    return ConfigError(where + ": larger than " +
                       std::to_string(mib ? max_bytes >> 20 : max_bytes) +
                       (mib ? " MiB" : " bytes"));
  };
  if (static_cast<std::size_t>(st.st_size) > max_bytes) throw too_large();
  std::string text(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t n = 0;
  for (;;) {  // read to the end, but never past the limit (the file may grow meanwhile)
    if (n == text.size()) {
      if (text.size() > max_bytes) throw too_large();
      text.resize(text.size() + 4096);
    }
    const ssize_t got = ::read(f.fd, text.data() + n, text.size() - n);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw ConfigError(where + ": " + std::strerror(errno));
    if (got == 0) break;
    n += static_cast<std::size_t>(got);
  }
  text.resize(n);
  if (n > max_bytes) throw too_large();
  return text;
}

}  // namespace rig::io::config
