#include "io/limits.h"

#include <mutex>

namespace sn::io {

namespace {
std::mutex g_mutex;
Limits g_limits;
}  // namespace

Limits limits() {
  std::lock_guard lock(g_mutex);
  return g_limits;
}

void set_limits(const Limits& l) {
  std::lock_guard lock(g_mutex);
  g_limits = l;
}

std::string raise_hint(const char* name) { return std::string(" (sn.limits{ ") + name + " = ... } raises it)"; }

}  // namespace sn::io
