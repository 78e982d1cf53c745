#include "io/atomic_write.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace sn::io {

void write_file_atomic(const std::string& path, const std::string& bytes, const std::string& what) {
  namespace fs = std::filesystem;
  const std::string head = "cannot write " + what + " '" + path + "': ";
  if (path.empty()) throw std::invalid_argument(head + "the path is empty");
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec) throw std::runtime_error(head + "cannot create folder '" + target.parent_path().string() + "': " + ec.message());
  }
  // Hidden, per process, in the target's folder: rename is atomic only within one filesystem.
  const std::string tmp =
      (target.parent_path() / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(head + std::strerror(errno));
  auto fail = [&](int err) {
    ::unlink(tmp.c_str());
    throw std::runtime_error(head + std::strerror(err));
  };
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      ::close(fd);
      fail(err);
    }
    done += std::size_t(n);
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    fail(err);
  }
  if (::close(fd) != 0) fail(errno);
  if (::rename(tmp.c_str(), path.c_str()) != 0) fail(errno);
}

}  // namespace sn::io
