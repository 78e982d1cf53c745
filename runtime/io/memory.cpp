#include "io/memory.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace sn::io {

namespace {
constexpr std::uint64_t kChecked = std::uint64_t(64) << 20;
constexpr std::uint64_t kMargin = std::uint64_t(256) << 20;

std::string gib(std::uint64_t bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f GiB", double(bytes) / double(std::uint64_t(1) << 30));
  return b;
}
}  // namespace

std::uint64_t available_memory() {
  std::FILE* f = std::fopen("/proc/meminfo", "r");
  if (!f) return 0;
  char line[256];
  unsigned long long kib = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "MemAvailable: %llu kB", &kib) == 1) break;
  std::fclose(f);
  return std::uint64_t(kib) * 1024;
}

void check_memory(std::uint64_t bytes, const std::string& what) {
  if (bytes < kChecked) return;
  const std::uint64_t free = available_memory();
  if (free == 0 || bytes + kMargin <= free) return;
  throw std::runtime_error(what + " needs " + gib(bytes) + " of memory; this machine has " + gib(free) +
                           " available (MemAvailable): a smaller size, or more free memory");
}

}  // namespace sn::io
