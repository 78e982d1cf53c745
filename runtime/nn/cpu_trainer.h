// The cpu backend: native training on this machine's cores. Each network trains on one thread
// (nn/cpu_net.h: SIMD across the minibatch); networks are spread over threads, in lockstep per
// epoch so the epoch permutation and Adam constants are computed once for all of them.
#pragma once
#include <cstddef>
#include <memory>

#include "nn/trainer.h"

namespace sn::nn {

// threads <= 0: io::default_threads() (io/parallel.h). shared_bytes: the most the packed epochs
// that nets of one shuffle share may take (beyond it each net packs its own; the same numbers).
std::unique_ptr<Backend> make_cpu_backend(int threads);
std::unique_ptr<Backend> make_cpu_backend(int threads, std::size_t shared_bytes);

}  // namespace sn::nn
