// The cpu backend: native training on this machine's cores. Each network trains on one thread
// (nn/cpu_net.h: SIMD across the minibatch); networks are spread over threads, in lockstep per
// epoch so the epoch permutation and Adam constants are computed once for all of them.
#pragma once
#include <memory>

#include "nn/trainer.h"

namespace sn::nn {

// threads <= 0: io::default_threads() (io/parallel.h).
std::unique_ptr<Backend> make_cpu_backend(int threads);

}  // namespace sn::nn
