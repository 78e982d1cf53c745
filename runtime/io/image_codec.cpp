#include "io/image_codec.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace sn::io {

namespace {

// SHADENET_IMAGE_MODULE when set (a packager's layout); else beside the running program (a build
// folder moved whole), else where the build put it.
std::vector<std::string> module_paths() {
  if (const char* env = std::getenv("SHADENET_IMAGE_MODULE")) return {env};
  std::vector<std::string> paths;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) paths.push_back((exe.parent_path() / "libshadenet_image.so").string());
  paths.push_back(SHADENET_IMAGE_MODULE);
  return paths;
}

const ImageCodec* load() {
  std::string reasons;
  for (const auto& path : module_paths()) {
    if (!std::filesystem::exists(path)) {
      reasons += "\n  " + path + ": no such file";
      continue;
    }
    // RTLD_LOCAL: OpenImageIO's libraries stay out of the program's global symbol scope.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      reasons += "\n  " + path + ": " + dlerror();
      continue;
    }
    using Entry = const ImageCodec* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(handle, "shadenet_image_codec"));
    const ImageCodec* codec = entry ? entry() : nullptr;
    if (codec && codec->version == kImageCodecVersion) return codec;
    reasons += "\n  " + path + ": not this build's image module";
    dlclose(handle);
  }
  throw std::runtime_error("cannot load the image module (OpenImageIO), needed to read, write or label images:" +
                           reasons +
                           (std::getenv("SHADENET_IMAGE_MODULE")
                                ? "\n  point SHADENET_IMAGE_MODULE at this build's libshadenet_image.so, or unset it"
                                : "\n  rebuild shadenet (cmake --build build)"));
}

}  // namespace

const ImageCodec& image_codec() {
  static std::once_flag once;
  static const ImageCodec* codec = nullptr;
  std::call_once(once, [] { codec = load(); });  // a failed load throws, and the next call tries again
  return *codec;
}

}  // namespace sn::io
