// Numbers as text, one way each: "%g" for messages people read, "%a" (exact) for cache keys.
#pragma once
#include <cstdio>
#include <string>

namespace sn::io {

inline std::string number_text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

// Every bit of the value: two keys are equal only when the doubles are.
inline std::string exact_text(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%a", v);
  return b;
}

}  // namespace sn::io
