#include "io/temp_dir.h"

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace sn::io {

namespace fs = std::filesystem;

namespace {

std::string temp_root() {
  const char* tmp = std::getenv("TMPDIR");
  return tmp && *tmp ? tmp : "/tmp";
}

}  // namespace

int remove_abandoned_temp_dirs(const std::string& tag, double min_age_seconds) {
  const std::string prefix = "shadenet-" + tag + "-";
  std::error_code ec;
  const auto now = fs::file_time_type::clock::now();
  std::vector<fs::path> abandoned;
  for (const auto& e : fs::directory_iterator(temp_root(), ec)) {
    const std::string name = e.path().filename().string();
    // mkdtemp's six characters after the prefix: "shadenet-plot-x1" is not another tag's folder.
    if (name.size() != prefix.size() + 6 || name.compare(0, prefix.size(), prefix) != 0) continue;
    if (!e.is_directory(ec) || e.is_symlink(ec)) continue;
    const auto changed = fs::last_write_time(e.path(), ec);
    if (ec || std::chrono::duration<double>(now - changed).count() < min_age_seconds) continue;
    // Held by a live TempDir: busy. (Where locks are unsupported nothing is known: kept.)
    if (FileLock::acquire(e.path().string(), FileLock::Mode::exclusive, false).held()) abandoned.push_back(e.path());
  }
  int removed = 0;
  for (const auto& p : abandoned) removed += fs::remove_all(p, ec) > 0 && !ec;
  return removed;
}

TempDir::TempDir(const std::string& tag) {
  if (tag.empty() || tag.find('/') != std::string::npos)
    throw std::invalid_argument("a scratch folder's tag must be a non-empty name without '/', got '" + tag + "'");
  remove_abandoned_temp_dirs(tag);
  std::string pattern = temp_root() + "/shadenet-" + tag + "-XXXXXX";
  if (!mkdtemp(pattern.data()))
    throw std::runtime_error("cannot make a scratch folder " + pattern + ": " + std::strerror(errno));
  path_ = pattern;
  lock_ = FileLock::acquire(path_, FileLock::Mode::shared);
}

TempDir::~TempDir() {
  std::error_code ec;  // a destructor cannot throw; what cannot be removed stays
  std::filesystem::remove_all(path_, ec);
}

}  // namespace sn::io
