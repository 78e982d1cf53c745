// Seeded random numbers that are the same on every platform (std distributions are not).
#pragma once
#include <cstdint>

namespace sn::data {

// splitmix64 (Steele, Lea, Flood 2014).
struct SplitMix {
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, n) without modulo bias (Lemire's multiply-shift with rejection).
  uint64_t below(uint64_t n) {
    for (;;) {
      unsigned __int128 m = (unsigned __int128)next() * n;
      uint64_t lo = uint64_t(m);
      if (lo >= (0 - n) % n) return uint64_t(m >> 64);
    }
  }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }
};

}  // namespace sn::data
