#include "io/atomic_write.h"

#include <fcntl.h>
#include <linux/magic.h>
#include <poll.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <set>
#include <stdexcept>

namespace sn::io {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxLinks = 40;            // as the kernel follows in one path (ELOOP beyond)
constexpr std::size_t kNameMax = 255;    // NAME_MAX of Linux file systems
constexpr std::size_t kTempDigits = 12;  // random: a name nobody can plant a link under beforehand

std::string head(const std::string& path, const std::string& what) { return "cannot write " + what + " '" + path + "': "; }

// A link in /proc's fd folders (/proc/self/fd/1, where /dev/stdout leads): its target text
// ("pipe:[123]", "/x (deleted)") names an open file, not a path to put a file beside.
bool in_proc(const fs::path& link) {
  struct statfs s {};
  const fs::path folder = link.has_parent_path() ? link.parent_path() : fs::path(".");
  return ::statfs(folder.c_str(), &s) == 0 && s.f_type == PROC_SUPER_MAGIC;
}

// through_links; a loop or an unreadable link is an error starting with `why` where given.
std::string follow_links(const std::string& path, const std::string* why, bool* into_proc) {
  fs::path p = path;
  for (int n = 0;; ++n) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p.string();
    if (in_proc(p)) {
      if (into_proc) *into_proc = true;
      return p.string();
    }
    if (n == kMaxLinks) {
      if (!why) return p.string();
      throw std::runtime_error(*why + "more than " + std::to_string(kMaxLinks) + " symbolic links in a row (a loop?)");
    }
    std::error_code ec;
    const fs::path to = fs::read_symlink(p, ec);
    if (ec && !why) return p.string();
    if (ec) throw std::runtime_error(*why + "cannot read the link '" + p.string() + "': " + ec.message());
    // Relative to the link's folder, not lexically normalised: "dir/../x" is resolved by the
    // kernel, which takes ".." from where a linked "dir" really is.
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
}

// N when `link` is /proc/self/fd/N, however reached (/dev/fd/N, /dev/stdout): a descriptor of
// this process; -1 otherwise.
int own_descriptor(const fs::path& link) {
  std::error_code ec;
  const std::string folder = fs::canonical(link.parent_path(), ec).string();  // /proc/self -> /proc/PID
  const std::string proc = "/proc/" + std::to_string(::getpid()) + "/";
  const bool ours = !ec && folder.compare(0, proc.size(), proc) == 0 &&
                    (folder.size() == proc.size() + 2 || folder.compare(proc.size(), 5, "task/") == 0) &&
                    folder.compare(folder.size() - 3, 3, "/fd") == 0;
  const std::string n = link.filename().string();
  if (!ours || n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stoi(n);
}

// Where a write to a path goes, and how.
struct Target {
  std::string path;       // the file (links followed), or the path as given for a stream
  bool straight = false;  // written into, never replaced: a device, FIFO, socket, or a file open in /proc
  int fd = -1;            // this process's descriptor the path leads to (/dev/stdout: 1), written through
  bool exists = false;
  struct stat st {};      // the existing file's (links followed): its mode and owner carry over
};

Target target_of(const std::string& path, const std::string& what) {
  const std::string why = head(path, what);
  if (path.empty()) throw std::invalid_argument(why + "the path is empty");
  Target t;
  bool in_proc = false;
  t.path = follow_links(path, &why, &in_proc);
  if (::stat(path.c_str(), &t.st) == 0) {
    t.exists = true;
    if (S_ISDIR(t.st.st_mode)) throw std::runtime_error(why + "it is a directory");
    // No old contents to keep, and replacing one would take it from its readers (a pipe's,
    // /dev/null's); a file open in /proc is one a process writes to (stdout sent to a file).
    t.straight = !S_ISREG(t.st.st_mode) || in_proc;
  }
  // Any other failure (a missing folder, no permission) is the writing's to report.
  if (t.straight) {
    if (in_proc) t.fd = own_descriptor(t.path);
    t.path = path;  // the kernel follows the links, /proc's too
  }
  return t;
}

// Writes all of `bytes`; 0 or the errno.
int write_all(int fd, const std::string& bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {  // a non-blocking pipe (ours, shared) is full
      pollfd p{fd, POLLOUT, 0};
      ::poll(&p, 1, -1);
      continue;
    }
    if (n <= 0) return n < 0 ? errno : EIO;
    done += std::size_t(n);
  }
  return 0;
}

// A stream or device: opened as it is, no O_CREAT or O_TRUNC. One of our descriptors (/dev/stdout)
// is written through, at its offset, as print() writes (opened anew, a file stdout is sent to
// would be written from its start, over what was printed). Another process's open file is
// appended to.
void write_into(const Target& t, const std::string& bytes, const std::string& what) {
  const std::string why = head(t.path, what);
  std::fflush(nullptr);  // what print() buffered goes first, in order, when this is our stdout
  if (t.fd >= 0) {
    if (const int err = write_all(t.fd, bytes)) throw std::runtime_error(why + std::strerror(err));
    return;
  }
  const int fd = ::open(t.path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | (S_ISREG(t.st.st_mode) ? O_APPEND : 0));
  if (fd < 0) {
    const int err = errno;
    throw std::runtime_error(why + std::strerror(err) + (S_ISSOCK(t.st.st_mode) ? " (a socket is not opened as a file)" : ""));
  }
  int err = write_all(fd, bytes);
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err) throw std::runtime_error(why + std::strerror(err));
}

// ".NAME.tmpDIGITS" beside `target` (rename is atomic only within one file system), NAME cut short
// (not inside a UTF-8 character) so that the whole fits NAME_MAX as any legal name does.
std::string temporary_stem(std::string name) {
  const std::size_t keep = kNameMax - 1 - 4 - kTempDigits;
  if (name.size() > keep) {
    std::size_t cut = keep;
    while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;
    name.resize(cut);
  }
  return name;
}

std::string temporary_name(const fs::path& target) {
  const std::string name = temporary_stem(target.filename().string());
  static thread_local std::random_device entropy;
  const uint64_t r = (uint64_t(entropy()) << 32) | entropy();
  std::string digits = std::to_string(r % 1000000000000ull);
  digits.insert(0, kTempDigits - digits.size(), '0');
  return (target.parent_path() / ("." + name + ".tmp" + digits)).string();
}

// Writes `bytes` to a new temporary file beside `t.path` (its folders created) with the old
// file's mode (and owner, where allowed), fsync'd when `sync`; returns its name. On failure
// nothing is left and the error names the path.
std::string write_temporary(const Target& t, const std::string& bytes, const std::string& what, bool sync) {
  const std::string why = head(t.path, what);
  const fs::path target(t.path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec) throw std::runtime_error(why + "cannot create folder '" + target.parent_path().string() + "': " + ec.message());
  }
  // O_EXCL: created here, never opened through a link or file planted under the name (a name
  // taken draws another). A new file gets 0666 less the umask, as other tools make them; a
  // replacement starts private and gets the old file's mode once written (a 0600 checkpoint
  // became 0644, world-readable).
  std::string tmp;
  int fd = -1;
  for (int tries = 0; fd < 0 && tries < 100; ++tries) {
    tmp = temporary_name(target);
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, t.exists ? 0600 : 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) throw std::runtime_error(why + std::strerror(errno));
  int err = write_all(fd, bytes);
  if (!err && t.exists) {
    // The owner as far as we may (root: any; others: a group of theirs), then the mode.
    if (t.st.st_uid != ::geteuid() || t.st.st_gid != ::getegid())
      (void)(::fchown(fd, t.st.st_uid, t.st.st_gid) == 0 || ::fchown(fd, uid_t(-1), t.st.st_gid) == 0);
    if (::fchmod(fd, t.st.st_mode & 0777) != 0) {
      // A file system without modes (vfat) refuses: wrong only where the new file is more open.
      err = errno;
      struct stat now {};
      if (::fstat(fd, &now) == 0 && (now.st_mode & 0777 & ~t.st.st_mode) == 0) err = 0;
    }
  }
  if (!err && sync && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && !err) err = errno;
  if (err) {
    ::unlink(tmp.c_str());
    throw std::runtime_error(why + std::strerror(err));
  }
  return tmp;
}

void rename_over(const std::string& tmp, const std::string& path, const std::string& what) {
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw std::runtime_error(head(path, what) + std::strerror(err));
  }
}

// Two paths of one file: the same inode, or for files yet to be made the same place.
std::string identity(const Target& t) {
  if (t.exists) return std::to_string(t.st.st_dev) + ":" + std::to_string(t.st.st_ino);
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(t.path, ec);
  return ec ? t.path : p.string();
}

}  // namespace

std::string through_links(const std::string& path) { return follow_links(path, nullptr, nullptr); }

void write_file_atomic(const std::string& path, const std::string& bytes, const std::string& what) {
  const Target t = target_of(path, what);
  if (t.straight) return write_into(t, bytes, what);
  rename_over(write_temporary(t, bytes, what, true), t.path, what);
}

void write_files_atomic(const std::vector<std::pair<std::string, std::string>>& files, const std::string& what,
                        const std::function<void()>& before_renames) {
  std::vector<Target> targets;
  std::set<std::string> seen;
  for (const auto& f : files) {
    targets.push_back(target_of(f.first, what));
    if (!seen.insert(identity(targets.back())).second) throw std::invalid_argument(head(f.first, what) + "the path is listed twice");
  }
  std::vector<std::string> temps(files.size());  // empty for the streams, written at their turn below
  const auto remove_temps = [&](std::size_t from) {
    for (std::size_t j = from; j < temps.size(); ++j)
      if (!temps[j].empty()) ::unlink(temps[j].c_str());
  };
  try {
    for (std::size_t i = 0; i < files.size(); ++i)
      if (!targets[i].straight) temps[i] = write_temporary(targets[i], files[i].second, what, false);
    // One flush per folder's file system (a folder stands for its file system; most calls have one).
    std::set<std::string> folders;
    for (const auto& t : targets) {
      if (t.straight) continue;
      const std::string folder = fs::path(t.path).parent_path().string();
      if (!folders.insert(folder.empty() ? "." : folder).second) continue;
      const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
      if (fd < 0 || ::syncfs(fd) != 0) {
        const int err = errno;
        if (fd >= 0) ::close(fd);
        throw std::runtime_error(head(t.path, what) + std::strerror(err));
      }
      ::close(fd);
    }
    if (before_renames) before_renames();
  } catch (...) {
    remove_temps(0);
    throw;
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    try {
      if (targets[i].straight) write_into(targets[i], files[i].second, what);
      else rename_over(temps[i], targets[i].path, what);
    } catch (...) {
      remove_temps(i + 1);
      throw;
    }
  }
}

int remove_stale_temporaries(const std::string& dir, double min_age_seconds, const std::vector<std::string>& names) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;
  std::set<std::string> stems;
  for (const auto& n : names) stems.insert(temporary_stem(n));
  const auto now = fs::file_time_type::clock::now();
  int removed = 0;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    const std::size_t at = name.rfind(".tmp");
    if (name.size() < 2 || name[0] != '.' || at == std::string::npos || at + 4 == name.size() ||
        name.find_first_not_of("0123456789", at + 4) != std::string::npos || !e.is_regular_file(ec))
      continue;
    if (!names.empty() && !stems.count(name.substr(1, at - 1))) continue;
    const auto written = fs::last_write_time(e.path(), ec);
    if (ec || std::chrono::duration<double>(now - written).count() < min_age_seconds) continue;
    if (fs::remove(e.path(), ec)) ++removed;
  }
  return removed;
}

}  // namespace sn::io
