// 64-bit FNV-1a: the one content hash for cache keys and checksums (not cryptographic).
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace sn::io {

struct Fnv1a {
  uint64_t h = 0xcbf29ce484222325ull;
  void bytes(const void* p, std::size_t n) {
    auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 0x100000001b3ull;
  }
  void text(const std::string& s) { bytes(s.data(), s.size()); }
  // The length first, so {ab}{c} and {a}{bc} differ.
  template <class T>
  void vec(const std::vector<T>& v) {
    uint64_t n = v.size();
    bytes(&n, sizeof n);
    if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
  }
};

inline uint64_t fnv1a(const std::string& s) {
  Fnv1a f;
  f.text(s);
  return f.h;
}

// 16 lowercase hex digits: how keys print a hash.
inline std::string hex64(uint64_t v) {
  char b[20];
  std::snprintf(b, sizeof b, "%016llx", (unsigned long long)v);
  return b;
}

}  // namespace sn::io
