// A scratch folder that removes itself: TMPDIR (or /tmp)/shadenet-TAG-XXXXXX, made with mkdtemp
// (so parallel processes never share one) and removed with everything in it by the destructor:
// at a script's end, by an error too, or a test's. A process ended by a signal leaves it behind.
#pragma once
#include <string>

namespace sn::io {

class TempDir {
 public:
  // Throws naming the folder and the reason when it cannot be made; `tag` may not hold '/'.
  explicit TempDir(const std::string& tag);
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace sn::io
