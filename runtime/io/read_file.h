// Reading a whole file, with errors that say which file and why: the counterpart of
// write_file_atomic.
#pragma once
#include <string>

namespace sn::io {

// Throws "cannot read <what> '<path>': <cause>" for a missing file, a directory or other
// non-regular file, or a failed read.
std::string read_file(const std::string& path, const std::string& what = "file");

}  // namespace sn::io
