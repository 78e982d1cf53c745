// This machine's FP32 fused multiply-add peak, per core and over all cores, with AVX2 (8 lanes)
// and AVX-512 (16 lanes): the ceiling bench/train_throughput.lua measures the cpu kernels
// against (its roofline columns), taken on the machine it runs on, not from a datasheet.
//
//   build/fma_peak [seconds]      seconds per measurement, 0.01 to 60 (default 0.3); best of 5 per figure
//
// Each thread runs 12 independent FMA chains (more than latency x pipes on current x86 cores,
// so the chains never wait on each other) for a fixed number of iterations; FLOP = 2 per lane
// per FMA. Prints one line per instruction set the CPU has:
//   avx2 per_core_gflops=123.4 all_cores_gflops=245.6 threads=2
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

namespace {

constexpr int kChains = 12;

typedef float v8 __attribute__((vector_size(32)));
typedef float v16 __attribute__((vector_size(64)));

// kChains chains of c = c * m + b (one FMA each: GCC contracts it), unrolled so that every
// chain stays in a register; the result goes to `sink` so the loop cannot be dropped.
template <class V>
inline __attribute__((always_inline)) float chains(long iters) {
  V a[kChains];
  const V m = V{} + 0.999999f, b = V{} + 1e-7f;
#pragma GCC unroll 12
  for (int c = 0; c < kChains; ++c) a[c] = V{} + (1.0f + 0.001f * c);
  for (long i = 0; i < iters; ++i) {
#pragma GCC unroll 12
    for (int c = 0; c < kChains; ++c) a[c] = a[c] * m + b;
  }
  V s = a[0];
#pragma GCC unroll 12
  for (int c = 1; c < kChains; ++c) s += a[c];
  return s[0];
}
__attribute__((target("avx2,fma"))) float chains_avx2(long iters) { return chains<v8>(iters); }
__attribute__((target("avx512f"))) float chains_avx512(long iters) { return chains<v16>(iters); }

volatile float sink;

// GFLOP/s of `threads` threads each running fn(iters), best of 5 (the iteration count is
// sized from a first run to last about `seconds`).
double measure(float (*fn)(long), int lanes, int threads, double seconds) {
  using clock = std::chrono::steady_clock;
  long iters = 1 << 16;
  for (;;) {  // size the run
    const auto t0 = clock::now();
    sink = fn(iters);
    const double t = std::chrono::duration<double>(clock::now() - t0).count();
    if (t > 0.02) {
      iters = long(double(iters) * seconds / t) + 1;
      break;
    }
    iters *= 4;
  }
  double best = 0;
  for (int rep = 0; rep < 5; ++rep) {
    std::vector<std::thread> pool;
    const auto t0 = clock::now();
    for (int k = 0; k < threads; ++k) pool.emplace_back([&] { sink = fn(iters); });
    for (auto& t : pool) t.join();
    const double t = std::chrono::duration<double>(clock::now() - t0).count();
    best = std::max(best, 2.0 * lanes * kChains * double(iters) * threads / t / 1e9);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  // Below 0.01 s starting the threads weighs on the figure (1e-9 timed one iteration: 0.0 GFLOP/s).
  constexpr double kMin = 0.01, kMax = 60;
  double seconds = 0.3;
  if (argc > 2) {
    std::fprintf(stderr, "fma_peak: %d arguments given, it takes at most 1\nusage: fma_peak [seconds]\n", argc - 1);
    return 2;
  }
  if (argc > 1) {
    char* end = nullptr;
    seconds = std::strtod(argv[1], &end);
    if (end == argv[1] || *end != '\0' || !(seconds >= kMin && seconds <= kMax)) {
      std::fprintf(stderr, "fma_peak: seconds '%s': expected seconds per measurement, %g to %g\nusage: fma_peak [seconds]\n",
                   argv[1], kMin, kMax);
      return 2;
    }
  }
  const int threads = std::max(1u, std::thread::hardware_concurrency());
  __builtin_cpu_init();
  struct Isa {
    const char* name;
    bool present;
    float (*fn)(long);
    int lanes;
  } isas[] = {{"avx2", __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"), chains_avx2, 8},
              {"avx512", __builtin_cpu_supports("avx512f") != 0, chains_avx512, 16}};
  for (const Isa& isa : isas) {
    if (!isa.present) continue;
    const double one = measure(isa.fn, isa.lanes, 1, seconds);
    const double all = measure(isa.fn, isa.lanes, threads, seconds);
    std::printf("%s per_core_gflops=%.1f all_cores_gflops=%.1f threads=%d\n", isa.name, one, all, threads);
  }
  return 0;
}
