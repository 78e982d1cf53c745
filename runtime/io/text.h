// Text for messages and keys. Numbers as text, one way each: "%g" for messages people read, "%a" (exact) for cache keys.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

namespace sn::io {

inline std::string number_text(double v) {
  if (v != v) return "nan";  // printf gives "-nan" for Lua's 0/0
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

// "a, b, c": the lists of valid choices in messages.
inline std::string join(const std::vector<std::string>& items, const char* sep = ", ") {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? sep : "") + items[i];
  return s;
}

}  // namespace sn::io
