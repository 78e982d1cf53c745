// Memory asked for in one large piece (an image, a render target or buffer in a software GL
// driver's host memory) is checked first against what the machine has free: past it, Linux's
// overcommit lets the allocation succeed and the kernel kills the process when the pages are
// touched (a 16384 x 16384 render on llvmpipe needs ~19 GB; on a 24 GB machine it was killed,
// taking the session's unsaved work with it). An error names the piece and both sizes.
#pragma once
#include <cstdint>
#include <string>

namespace sn::io {

// The memory the machine can give without swapping (/proc/meminfo's MemAvailable), in bytes; 0
// when it cannot be read.
std::uint64_t available_memory();

// Throws std::runtime_error when `bytes` (at least 64 MiB: smaller pieces are not checked) is more
// than available_memory() less a 256 MiB margin for the rest of the process. `what` reads "a
// 16384x16384 render target with 3 attachment(s)".
void check_memory(std::uint64_t bytes, const std::string& what);

}  // namespace sn::io
