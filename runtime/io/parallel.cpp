#include "io/parallel.h"

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <system_error>

namespace sn::io {

// More threads than any machine's cores only queue: a typo such as 20000 is refused.
constexpr long kMaxThreads = 1024;

int default_threads() {
  // SHADENET_THREADS checked: "abc" and 0 ran on every core without a word. (A throw leaves the
  // static unset, so every call says it.)
  static const int threads = [] {
    const unsigned hw = std::thread::hardware_concurrency();
    const char* env = std::getenv("SHADENET_THREADS");
    if (!env || !*env) return hw ? int(hw) : 1;
    char* end = nullptr;
    const long n = std::strtol(env, &end, 10);
    if (*end || n < 1 || n > kMaxThreads)
      throw std::invalid_argument(std::string("SHADENET_THREADS='") + env + "' is not a whole number of threads in 1.." +
                                  std::to_string(kMaxThreads) + " (unset: all " + std::to_string(hw ? hw : 1) +
                                  " cores)");
    return int(n);
  }();
  return threads;
}

namespace detail {

namespace {

// How long a thread spins before it sleeps: waiting for the next call (an image's render and
// its SSIM come tens of microseconds apart) or for the helpers to finish. Waking a sleeping
// thread costs more than that on this kind of machine.
constexpr auto kSpin = std::chrono::microseconds(100);

// Threads that wait for work between parallel_for calls. One call holds the pool at a time.
// The counters are atomic so that a spinning thread sees work without the mutex; the mutex and
// condition variables are for the threads that sleep.
struct Pool {
  std::mutex m;
  std::condition_variable wake, finished;
  std::atomic<const std::function<void()>*> work{nullptr};
  std::atomic<int> wanted{0};   // helpers still to take the current work
  std::atomic<int> running{0};  // helpers inside it (or about to take it)
  std::atomic<int> sleeping{0};
  int started = 0;
  std::atomic<bool> held{false};
};

// Never destroyed: its threads wait in it until the process ends.
Pool& pool() {
  static Pool* p = new Pool;
  return *p;
}

// Spins on ready() for kSpin, then returns whether it became true.
template <class Ready>
bool spin(Ready&& ready) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (int i = 0;; ++i) {
    if (ready()) return true;
    if ((i & 63) == 63 && std::chrono::steady_clock::now() > until) return false;
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
}

void left(Pool& p) {
  if (p.running.fetch_sub(1) == 1) {
    std::lock_guard lock(p.m);
    p.finished.notify_all();
  }
}

void helper(Pool& p) {
  for (;;) {
    const auto has_work = [&] { return p.wanted.load() > 0; };
    if (!spin(has_work)) {
      std::unique_lock lock(p.m);
      ++p.sleeping;
      p.wake.wait(lock, has_work);
      --p.sleeping;
    }
    // Counted as running before taking a slot, so that the caller, once it has seen no one
    // running, knows that no one will take one of its slots.
    p.running.fetch_add(1);
    int w = p.wanted.load();
    while (w > 0 && !p.wanted.compare_exchange_weak(w, w - 1)) {
    }
    if (w > 0) (*p.work.load())();
    left(p);
  }
}

}  // namespace

bool run_on_pool(int helpers, const std::function<void()>& work) {
  Pool& p = pool();
  if (p.held.exchange(true)) return false;
  {
    std::lock_guard lock(p.m);
    try {
      for (; p.started < helpers; ++p.started) std::thread(helper, std::ref(p)).detach();
    } catch (const std::system_error&) {  // no more threads: those started do the work
      if (p.started == 0) {
        p.held = false;
        return false;
      }
    }
  }
  p.work = &work;
  p.wanted = std::min(helpers, p.started);
  if (p.sleeping.load() > 0) {
    std::lock_guard lock(p.m);
    p.wake.notify_all();
  }
  work();
  p.wanted = 0;  // a helper that has not taken a slot yet is not needed: the queue is empty
  const auto done = [&] { return p.running.load() == 0; };
  if (!spin(done)) {
    std::unique_lock lock(p.m);
    p.finished.wait(lock, done);
  }
  p.held = false;
  return true;
}

}  // namespace detail

}  // namespace sn::io
