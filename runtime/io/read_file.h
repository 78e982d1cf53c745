// Reading a whole file, with errors that say which file and why: the counterpart of
// write_file_atomic.
#pragma once
#include <cstdint>
#include <string>

namespace sn::io {

// The default cap on what one read may hold.
constexpr std::uint64_t kMaxReadBytes = std::uint64_t(1) << 30;  // 1 GiB

// Throws "cannot read <what> '<path>': <cause>" for a missing file, a directory or other
// non-regular file (/dev/zero, a FIFO), a file larger than `max_bytes`, or a failed read.
std::string read_file(const std::string& path, const std::string& what = "file", std::uint64_t max_bytes = kMaxReadBytes);

}  // namespace sn::io
