#include "io/read_file.h"

#include "io/limits.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace sn::io {

std::string read_file(const std::string& path, const std::string& what, std::uint64_t max_bytes, const char* limit) {
  if (max_bytes == 0) max_bytes = limits().file_bytes;
  const std::string head = "cannot read " + what + " '" + path + "': ";
  // O_NONBLOCK: opening a FIFO would otherwise wait for a writer; regular files ignore it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    std::string why = errno == ENOENT ? "no such file" : std::strerror(errno);
    // A relative path is read from the working directory: name it (a script run from elsewhere
    // than the directory its paths assume fails here).
    char cwd[4096];
    if (errno == ENOENT && !path.empty() && path[0] != '/' && ::getcwd(cwd, sizeof cwd))
      why += " (relative to the working directory " + std::string(cwd) + ")";
    throw std::runtime_error(head + why);
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    throw std::runtime_error(head + std::strerror(err));
  }
  if (!S_ISREG(st.st_mode)) {
    const bool dir = S_ISDIR(st.st_mode);
    ::close(fd);
    throw std::runtime_error(head + (dir ? "it is a directory" : "not a regular file"));
  }
  if (std::uint64_t(st.st_size) > max_bytes) {
    ::close(fd);
    throw std::runtime_error(head + std::to_string(st.st_size) + " bytes, above the limit of " + std::to_string(max_bytes) +
                             " bytes" + raise_hint(limit));
  }
  std::string bytes(std::size_t(st.st_size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      throw std::runtime_error(head + std::strerror(err));
    }
    if (n == 0) break;  // shrank while we read
    done += std::size_t(n);
  }
  ::close(fd);
  bytes.resize(done);
  return bytes;
}

}  // namespace sn::io
