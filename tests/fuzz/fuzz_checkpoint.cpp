// Fuzz target: sn.load of a network checkpoint (nn/checkpoint.h). Mutations nearly always break
// the checksum, which would stop every input at the header; the header's size and checksum are
// therefore made to match the mutated payload so the fuzzer reaches the payload parser (the
// header checks have their own regression tests in tests/unit/test_checkpoint.cpp).
// Whatever loads must save and load again to the same parameters.
#include <cstring>
#include <exception>
#include <vector>

#include "fuzz_input.h"
#include "io/hash.h"
#include "nn/checkpoint.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::vector<uint8_t> bytes(data, data + size);
  if (bytes.size() >= 24) {
    uint32_t payload = uint32_t(bytes.size() - 24);
    std::memcpy(&bytes[12], &payload, 4);
    sn::io::Fnv1a sum;
    sum.bytes(bytes.data() + 24, payload);
    std::memcpy(&bytes[16], &sum.h, 8);
  }
  std::string path = sn::fuzz::scratch_file("input.snmlp", bytes.data(), bytes.size());
  sn::nn::Mlp net;
  try {
    net = sn::nn::load_checkpoint(path);
  } catch (const std::exception&) {
    return 0;
  }
  std::string again = sn::fuzz::scratch_dir() + "/again.snmlp";
  sn::nn::save_checkpoint(net, again);
  sn::nn::Mlp back = sn::nn::load_checkpoint(again);
  // Bytes, not values: a NaN parameter must round-trip too.
  if (back.params.size() != net.params.size() ||
      std::memcmp(back.params.data(), net.params.data(), net.params.size() * sizeof(float)) != 0)
    __builtin_trap();
  return 0;
}
