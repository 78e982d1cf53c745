#include "io/numbered_path.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <stdexcept>

namespace sn::io {

namespace {

// Tries dir/stem-0001<ext>, dir/stem-0002<ext>, ... with `create`, which returns 0 when it made
// the name, EEXIST when the name was taken, another errno when it cannot create anything.
std::string claim(const std::string& dir, const std::string& stem, const std::string& ext, const char* what,
                  const std::function<int(const std::string&)>& create) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create folder '" + dir + "': " + ec.message());
  for (int i = 1; i < 1000000; ++i) {
    char name[64];
    snprintf(name, sizeof name, "%04d", i);
    std::string path = dir + "/" + stem + "-" + name + ext;
    int err = create(path);
    if (err == 0) return path;
    if (err != EEXIST)
      throw std::runtime_error(std::string("cannot create the ") + what + " '" + path + "': " + strerror(err));
  }
  throw std::runtime_error("no free " + std::string(what) + " name " + stem + "-NNNN" + ext + " in '" + dir + "'");
}

}  // namespace

std::string claim_numbered_file(const std::string& dir, const std::string& stem, const std::string& ext) {
  return claim(dir, stem, ext, "file", [](const std::string& p) {
    int fd = open(p.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) return errno;
    close(fd);
    return 0;
  });
}

std::string claim_numbered_dir(const std::string& dir, const std::string& stem) {
  return claim(dir, stem, "", "folder", [](const std::string& p) { return mkdir(p.c_str(), 0755) == 0 ? 0 : errno; });
}

}  // namespace sn::io
