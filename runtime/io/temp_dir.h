// A scratch folder that removes itself: TMPDIR (or /tmp)/shadenet-TAG-XXXXXX, made with mkdtemp
// (so parallel processes never share one) and removed with everything in it by the destructor:
// at a script's end, by an error too, or a test's. A process ended by a signal leaves it behind;
// its holder keeps a lock on it (io/file_lock.h) while it lives, so the next folder made with the
// same tag removes those that no process holds any more once they are a minute old (a killed
// plot's folders piled up in TMPDIR).
#pragma once
#include <string>

#include "io/file_lock.h"

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
  FileLock lock_;
};

// Removes the folders TMPDIR/shadenet-TAG-XXXXXX that no live TempDir holds and that were last
// changed `min_age_seconds` ago or earlier (a folder just made is locked a moment later); returns
// how many.
int remove_abandoned_temp_dirs(const std::string& tag, double min_age_seconds = 60);

}  // namespace sn::io
