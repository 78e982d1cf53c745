#include "io/temp_dir.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace sn::io {

TempDir::TempDir(const std::string& tag) {
  if (tag.empty() || tag.find('/') != std::string::npos)
    throw std::invalid_argument("a scratch folder's tag must be a non-empty name without '/', got '" + tag + "'");
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/shadenet-" + tag + "-XXXXXX";
  if (!mkdtemp(pattern.data()))
    throw std::runtime_error("cannot make a scratch folder " + pattern + ": " + std::strerror(errno));
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ec;  // a destructor cannot throw; what cannot be removed stays
  std::filesystem::remove_all(path_, ec);
}

}  // namespace sn::io
