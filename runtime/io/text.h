// Text for messages and keys. Numbers as text, one way each: "%g" for messages people read, "%a" (exact) for cache keys.
#pragma once
#include <cmath>
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

// v as number_text writes it, but a whole number in full: a count of 2^32 + 1 must not read as
// 4.29497e+09 in a message saying it is out of range.
inline std::string whole_text(double v) {
  if (v == std::floor(v) && std::abs(v) < 0x1p63) return std::to_string((long long)v);
  return number_text(v);
}

// v as number_text writes it, with more digits where those would read as `apart`: a value just
// outside a range must not print as its bound (0.8000001 against 0.8).
inline std::string number_text(double v, double apart) {
  char b[32], c[32];
  for (int digits = 6; digits < 17; ++digits) {
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    std::snprintf(c, sizeof c, "%.*g", digits, apart);
    if (v == apart || std::string(b) != c) return v == v ? b : "nan";
  }
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// "{x, y, z}": a direction or colour in messages, number_text per component (any type with x, y, z).
template <class V>
std::string vec3_text(const V& v) {
  return "{" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + "}";
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
