#include "io/atomic_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>
#include <set>
#include <stdexcept>

namespace sn::io {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kNameMax = 255;    // NAME_MAX of Linux file systems
constexpr std::size_t kTempDigits = 12;  // random: a name nobody can plant a link under beforehand

std::string head(const std::string& path, const std::string& what) { return "cannot write " + what + " '" + path + "': "; }

// The file a write to `path` means: a symbolic link's target (renamed over, the link would become
// a file of its own and the file it points to keep the old bytes).
std::string through_links(const std::string& path) {
  std::error_code ec;
  if (!fs::is_symlink(path, ec)) return path;
  const fs::path real = fs::weakly_canonical(path, ec);
  return ec ? path : real.string();
}

// ".NAME.tmpDIGITS" beside `target` (rename is atomic only within one file system), NAME cut short
// (not inside a UTF-8 character) so that the whole fits NAME_MAX as any legal name does.
std::string temporary_name(const fs::path& target) {
  std::string name = target.filename().string();
  const std::size_t keep = kNameMax - 1 - 4 - kTempDigits;
  if (name.size() > keep) {
    std::size_t cut = keep;
    while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;
    name.resize(cut);
  }
  static thread_local std::random_device random;
  const uint64_t r = (uint64_t(random()) << 32) | random();
  std::string digits = std::to_string(r % 1000000000000ull);
  digits.insert(0, kTempDigits - digits.size(), '0');
  return (target.parent_path() / ("." + name + ".tmp" + digits)).string();
}

// Writes `bytes` to a temporary file beside `path` (its folders created) with the old file's mode
// (and owner, where allowed), fsync'd when `sync`; returns its name. On failure nothing is left
// and the error names `path`.
std::string write_temporary(const std::string& path, const std::string& bytes, const std::string& what, bool sync) {
  const std::string why = head(path, what);
  if (path.empty()) throw std::invalid_argument(why + "the path is empty");
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec) throw std::runtime_error(why + "cannot create folder '" + target.parent_path().string() + "': " + ec.message());
  }
  struct stat old {};
  const bool replacing = ::stat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode);
  // O_EXCL: created here, never opened through a link or file planted under the name (a name
  // taken draws another). A new file gets 0666 less the umask, as other tools make them; a
  // replacement starts private and gets the old file's mode once written (a 0600 checkpoint
  // became 0644, world-readable).
  std::string tmp;
  int fd = -1;
  for (int tries = 0; fd < 0 && tries < 100; ++tries) {
    tmp = temporary_name(target);
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, replacing ? 0600 : 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) throw std::runtime_error(why + std::strerror(errno));
  int err = 0;
  for (std::size_t done = 0; done < bytes.size() && !err;) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) err = n < 0 ? errno : EIO;
    else done += std::size_t(n);
  }
  if (!err && replacing) {
    // The owner as far as we may (root: any; others: a group of theirs), then the mode.
    if (old.st_uid != ::geteuid() || old.st_gid != ::getegid())
      (void)(::fchown(fd, old.st_uid, old.st_gid) == 0 || ::fchown(fd, uid_t(-1), old.st_gid) == 0);
    if (::fchmod(fd, old.st_mode & 0777) != 0) {
      // A file system without modes (vfat) refuses: wrong only where the new file is more open.
      err = errno;
      struct stat now {};
      if (::fstat(fd, &now) == 0 && (now.st_mode & 0777 & ~old.st_mode) == 0) err = 0;
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

}  // namespace

void write_file_atomic(const std::string& link, const std::string& bytes, const std::string& what) {
  const std::string path = through_links(link);
  rename_over(write_temporary(path, bytes, what, true), path, what);
}

void write_files_atomic(const std::vector<std::pair<std::string, std::string>>& files, const std::string& what,
                        const std::function<void()>& before_renames) {
  std::vector<std::string> targets;  // the paths, through links
  std::set<std::string> paths;
  for (const auto& f : files) {
    targets.push_back(through_links(f.first));
    if (!paths.insert(targets.back()).second) throw std::invalid_argument(head(f.first, what) + "the path is listed twice");
  }
  std::vector<std::string> temps;
  const auto remove_temps = [&] {
    for (const auto& t : temps) ::unlink(t.c_str());
  };
  try {
    for (std::size_t i = 0; i < files.size(); ++i) temps.push_back(write_temporary(targets[i], files[i].second, what, false));
    // One flush per folder's file system (a folder stands for its file system; most calls have one).
    std::set<std::string> folders;
    for (const auto& path : targets) {
      const std::string folder = fs::path(path).parent_path().string();
      if (!folders.insert(folder.empty() ? "." : folder).second) continue;
      const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
      if (fd < 0 || ::syncfs(fd) != 0) {
        const int err = errno;
        if (fd >= 0) ::close(fd);
        throw std::runtime_error(head(path, what) + std::strerror(err));
      }
      ::close(fd);
    }
    if (before_renames) before_renames();
  } catch (...) {
    remove_temps();
    throw;
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    try {
      rename_over(temps[i], targets[i], what);
    } catch (...) {
      for (std::size_t j = i + 1; j < temps.size(); ++j) ::unlink(temps[j].c_str());
      throw;
    }
  }
}

int remove_stale_temporaries(const std::string& dir, double min_age_seconds) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;
  const auto now = fs::file_time_type::clock::now();
  int removed = 0;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    const std::size_t at = name.rfind(".tmp");
    if (name.size() < 2 || name[0] != '.' || at == std::string::npos || at + 4 == name.size() ||
        name.find_first_not_of("0123456789", at + 4) != std::string::npos || !e.is_regular_file(ec))
      continue;
    const auto written = fs::last_write_time(e.path(), ec);
    if (ec || std::chrono::duration<double>(now - written).count() < min_age_seconds) continue;
    if (fs::remove(e.path(), ec)) ++removed;
  }
  return removed;
}

}  // namespace sn::io
