// Advisory locks (flock(2)) on a file or a folder, held through an open descriptor: the kernel
// drops a lock when its holder ends, however it ends (a SIGKILL leaves nothing locked behind),
// and never two conflicting locks at once: many shared, or one exclusive. They keep cooperating
// processes apart (two exports to one dataset path, a reader and an exporter, two experiments
// claiming one results folder); a process that takes no lock is not stopped.
//
// Where the file system keeps no flock locks (some NFS and Lustre mounts refuse them, and NFS an
// exclusive lock on a folder), or the path cannot be opened, the lock is `unsupported`: callers go
// on without it, as they did before locks. A file this process holds a lock on already (through
// another FileLock) is not locked again, which would wait for ever (flock locks of two descriptors
// conflict, in one process too): that lock is `unsupported`, and the caller goes on under the
// first.
#pragma once
#include <string>

namespace sn::io {

class FileLock {
 public:
  enum class Mode { shared, exclusive };
  enum class State { unlocked, held, busy, unsupported };

  FileLock() = default;
  // Locks `path` (an existing file or folder; nothing is created), waiting for other holders when
  // `wait`; without it a conflicting holder gives State::busy at once. Signals that interrupt the
  // wait do not end it.
  static FileLock acquire(const std::string& path, Mode mode, bool wait = true);
  FileLock(FileLock&& o) noexcept;
  FileLock& operator=(FileLock&& o) noexcept;
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  ~FileLock();

  State state() const { return state_; }
  bool held() const { return state_ == State::held; }
  // Why the lock is unsupported ("Operation not supported", ...); empty otherwise.
  const std::string& why() const { return why_; }
  // An exclusive lock becomes shared (others may then share it; flock converts in place).
  void share();
  void release();

 private:
  int fd_ = -1;
  State state_ = State::unlocked;
  std::string why_;
};

}  // namespace sn::io
