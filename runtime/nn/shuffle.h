// The epoch permutation: row k of epoch e is training row shuffle_index(seed, e, k, n).
// Counter-based (no state, no sort), so every sample of every step can compute its own row on
// any backend; the gl kernel reproduces it bit-exactly with uint arithmetic:
//
//   uint mix32(uint x) {            // "lowbias32" (C. Wellons), a bijective 32-bit mix
//     x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16; return x; }
//   uint round_key(uint seed, uint epoch, uint r) {
//     return mix32(seed ^ mix32(epoch ^ mix32(r + 0x68e31da4u))); }
//   // a 4-round balanced Feistel network on 2*h bits, h = half_bits(n), is a bijection on
//   // [0, 4^h); "cycle walking" (re-applying it until the value is < n) restricts it to a
//   // bijection on [0, n). 4^h < 4n, so fewer than 4 applications are needed on average.
//   uint shuffle_index(uint seed, uint epoch, uint k, uint n) {
//     uint h = half_bits(n), mask = (1u << h) - 1u, x = k;
//     do {
//       uint l = x >> h, r = x & mask;
//       for (uint i = 0u; i < 4u; ++i) { uint t = r; r = l ^ (mix32(r ^ round_key(seed, epoch, i)) & mask); l = t; }
//       x = (l << h) | r;
//     } while (x >= n);
//     return x; }
//   half_bits(n) = max(1, ceil(bits(n - 1) / 2)), bits(v) = position of the highest set bit + 1
//   (bits(0) = 0).
//
// The four round keys depend only on (seed, epoch): compute them once per epoch (EpochShuffle).
#pragma once
#include <cstdint>

namespace sn::nn {

constexpr uint32_t mix32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

constexpr uint32_t shuffle_round_key(uint32_t seed, uint32_t epoch, uint32_t round) {
  return mix32(seed ^ mix32(epoch ^ mix32(round + 0x68e31da4u)));
}

constexpr uint32_t shuffle_half_bits(uint32_t n) {
  uint32_t bits = 0;
  for (uint32_t v = n - 1; v; v >>= 1) ++bits;
  uint32_t h = (bits + 1) / 2;
  return h < 1 ? 1 : h;
}

// The permutation of one epoch over n rows (n >= 1, n < 2^31).
class EpochShuffle {
 public:
  constexpr EpochShuffle(uint32_t seed, uint32_t epoch, uint32_t n)
      : n_(n), h_(shuffle_half_bits(n)), mask_((1u << shuffle_half_bits(n)) - 1u),
        key_{shuffle_round_key(seed, epoch, 0), shuffle_round_key(seed, epoch, 1),
             shuffle_round_key(seed, epoch, 2), shuffle_round_key(seed, epoch, 3)} {}

  constexpr uint32_t operator()(uint32_t k) const {
    uint32_t x = k;
    do {
      uint32_t l = x >> h_, r = x & mask_;
      for (uint32_t i = 0; i < 4; ++i) {
        uint32_t t = r;
        r = l ^ (mix32(r ^ key_[i]) & mask_);
        l = t;
      }
      x = (l << h_) | r;
    } while (x >= n_);
    return x;
  }

 private:
  uint32_t n_, h_, mask_;
  uint32_t key_[4];
};

constexpr uint32_t shuffle_index(uint32_t seed, uint32_t epoch, uint32_t k, uint32_t n) {
  return EpochShuffle(seed, epoch, n)(k);
}

}  // namespace sn::nn
