#include "io/parallel.h"

#include <cstdlib>
#include <system_error>

namespace sn::io {

int default_threads() {
  if (const char* env = std::getenv("SHADENET_THREADS")) {
    int n = std::atoi(env);
    if (n > 0) return n;
  }
  unsigned hw = std::thread::hardware_concurrency();
  return hw ? int(hw) : 1;
}

namespace detail {

namespace {

// Threads that wait for work between parallel_for calls. One call holds the pool at a time.
struct Pool {
  std::mutex m;
  std::condition_variable wake, finished;
  const std::function<void()>* work = nullptr;
  int wanted = 0;   // helpers still to take the current work
  int running = 0;  // helpers inside it
  int started = 0;
  std::atomic<bool> held{false};
};

// Never destroyed: its threads wait in it until the process ends.
Pool& pool() {
  static Pool* p = new Pool;
  return *p;
}

void helper(Pool& p) {
  std::unique_lock lock(p.m);
  for (;;) {
    p.wake.wait(lock, [&] { return p.wanted > 0; });
    --p.wanted;
    ++p.running;
    const std::function<void()>& work = *p.work;
    lock.unlock();
    work();
    lock.lock();
    if (--p.running == 0) p.finished.notify_all();
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
    p.work = &work;
    p.wanted = std::min(helpers, p.started);
  }
  p.wake.notify_all();
  work();
  {
    std::unique_lock lock(p.m);
    p.wanted = 0;  // a helper not awake yet is not needed: the queue is empty
    p.finished.wait(lock, [&] { return p.running == 0; });
    p.work = nullptr;
  }
  p.held = false;
  return true;
}

}  // namespace detail

}  // namespace sn::io
