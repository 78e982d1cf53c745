// Reading a whole file, with errors that say which file and why: the counterpart of
// write_file_atomic.
#pragma once
#include <cstdint>
#include <string>

namespace sn::io {

// Throws "cannot read <what> '<path>': <cause>" for a missing file, a directory or other
// non-regular file (/dev/zero, a FIFO), a file larger than `max_bytes`, or a failed read.
// `limit` names the io/limits.h field `max_bytes` came from, for the error's hint. Without
// them: limits().file_bytes.
std::string read_file(const std::string& path, const std::string& what = "file", std::uint64_t max_bytes = 0,
                      const char* limit = "file_bytes");

}  // namespace sn::io
