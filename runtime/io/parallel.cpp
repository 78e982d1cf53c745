#include "io/parallel.h"

#include <cstdlib>

namespace sn::io {

int default_threads() {
  if (const char* env = std::getenv("SHADENET_THREADS")) {
    int n = std::atoi(env);
    if (n > 0) return n;
  }
  unsigned hw = std::thread::hardware_concurrency();
  return hw ? int(hw) : 1;
}

}  // namespace sn::io
