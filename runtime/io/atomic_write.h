// Writing a whole file so that it is never half-written: the bytes go to a temporary file beside
// the target, every write, the flush, fsync and close are checked, then the temporary is renamed
// over the target. On any failure the old file is untouched, the temporary is removed and the
// error names the path and the cause ("No space left on device", ...).
#pragma once
#include <string>

namespace sn::io {

// Creates missing parent folders. `what` starts the message: "cannot write <what> '<path>': ...".
void write_file_atomic(const std::string& path, const std::string& bytes, const std::string& what = "file");

}  // namespace sn::io
