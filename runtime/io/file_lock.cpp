#include "io/file_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <mutex>
#include <set>
#include <utility>

namespace sn::io {

namespace {

// The files this process holds a lock on (device, inode): a second lock on one of them would
// wait for the first for ever (flock locks of two descriptors conflict, one process or not).
std::mutex held_mutex;
std::multiset<std::pair<dev_t, ino_t>> held_files;

std::pair<dev_t, ino_t> identity(int fd) {
  struct stat st {};
  ::fstat(fd, &st);
  return {st.st_dev, st.st_ino};
}

}  // namespace

FileLock FileLock::acquire(const std::string& path, Mode mode, bool wait) {
  FileLock l;
  // Read-only: a folder opens no other way, and a reader's file may be read-only to it. O_CLOEXEC:
  // a child (gnuplot) must not hold the lock after we end.
  l.fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY);
  if (l.fd_ < 0) {
    l.state_ = State::unsupported;
    l.why_ = std::string("cannot open '") + path + "': " + std::strerror(errno);
    return l;
  }
  {
    std::lock_guard<std::mutex> g(held_mutex);
    if (held_files.count(identity(l.fd_))) {  // ours already: go on under that lock
      ::close(l.fd_);
      l.fd_ = -1;
      l.state_ = State::unsupported;
      l.why_ = "this process holds a lock on it already";
      return l;
    }
  }
  const int op = (mode == Mode::shared ? LOCK_SH : LOCK_EX) | (wait ? 0 : LOCK_NB);
  int r;
  while ((r = ::flock(l.fd_, op)) != 0 && errno == EINTR) {
  }
  if (r == 0) {
    l.state_ = State::held;
    std::lock_guard<std::mutex> g(held_mutex);
    held_files.insert(identity(l.fd_));
    return l;
  }
  const int err = errno;
  ::close(l.fd_);
  l.fd_ = -1;
  if (err == EWOULDBLOCK) {
    l.state_ = State::busy;
  } else {  // ENOLCK, EOPNOTSUPP, ENOSYS, EBADF (NFS: an exclusive lock on a read-only descriptor), ...
    l.state_ = State::unsupported;
    l.why_ = std::strerror(err);
  }
  return l;
}

FileLock::FileLock(FileLock&& o) noexcept
    : fd_(std::exchange(o.fd_, -1)), state_(std::exchange(o.state_, State::unlocked)), why_(std::move(o.why_)) {}

FileLock& FileLock::operator=(FileLock&& o) noexcept {
  if (this != &o) {
    release();
    fd_ = std::exchange(o.fd_, -1);
    state_ = std::exchange(o.state_, State::unlocked);
    why_ = std::move(o.why_);
  }
  return *this;
}

FileLock::~FileLock() { release(); }

void FileLock::share() {
  if (fd_ < 0) return;
  while (::flock(fd_, LOCK_SH) != 0 && errno == EINTR) {
  }
}

void FileLock::release() {
  if (fd_ >= 0 && state_ == State::held) {
    std::lock_guard<std::mutex> g(held_mutex);
    const auto it = held_files.find(identity(fd_));
    if (it != held_files.end()) held_files.erase(it);
  }
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor of the open file drops its lock
  fd_ = -1;
  if (state_ == State::held) state_ = State::unlocked;
}

}  // namespace sn::io
