// Runs fn(i) for i in [0, n) on up to `threads` threads (the caller's included), handing out
// indices one at a time so uneven work balances. The first exception is rethrown after all
// threads have stopped. The other threads wait between calls (starting threads for each call
// cost more than a small image's render); a call made while another holds them starts its own.
// A call from inside fn (a render inside a batch of renders) runs on its caller alone: the
// threads are already busy with the outer work.
#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sn::io {

// Threads for work that splits (networks, image bands): SHADENET_THREADS if set, else the hardware's.
int default_threads();

namespace detail {
// Whether this thread is running a parallel_for's work.
inline thread_local bool t_in_work = false;

// Hands out the indices [0, n) one at a time to whichever thread calls run(); keeps the first
// exception and stops handing out work after it.
template <class Fn>
struct WorkQueue {
  WorkQueue(int count, Fn& f) : n(count), fn(f) {}
  int n;
  Fn& fn;
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  void run() {
    const bool outer = t_in_work;
    t_in_work = true;
    for (int i; (i = next.fetch_add(1)) < n;) {
      try {
        fn(i);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        next = n;
      }
    }
    t_in_work = outer;
  }
};

// Runs work() on the caller and on `helpers` waiting threads (started on first need), and returns
// once every one of them has left it; false, having run nothing, when another call holds them.
bool run_on_pool(int helpers, const std::function<void()>& work);
}  // namespace detail

template <class Fn>
void parallel_for(int n, int threads, Fn&& fn) {
  detail::WorkQueue<Fn> q(n, fn);
  const int extra = detail::t_in_work ? 0 : std::max(0, std::min(threads, n) - 1);
  if (extra == 0) {
    q.run();
  } else if (!detail::run_on_pool(extra, [&] { q.run(); })) {
    std::vector<std::thread> pool;
    pool.reserve(std::size_t(extra));
    for (int t = 0; t < extra; ++t) pool.emplace_back([&] { q.run(); });
    q.run();
    for (auto& t : pool) t.join();
  }
  if (q.error) std::rethrow_exception(q.error);
}

// When parallel_for_watched calls watch(): every `period`, on a fixed beat that carries over from
// one call to the next (work split into calls shorter than the period is still watched), and
// that watch()'s own time does not stretch.
struct WatchBeat {
  using Clock = std::chrono::steady_clock;
  explicit WatchBeat(double seconds)
      : period(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds))),
        due(Clock::now() + period) {}
  Clock::duration period;
  Clock::time_point due;
};

// parallel_for on `threads` threads of its own while the caller calls watch() on `beat` until
// they are done: the caller's thread stays free for what must run on it (a window's events and
// drawing during a long training epoch). watch() cannot end the work (fn must read a flag it
// sets); an exception from it is rethrown after the work, and watch() is not called again.
template <class Fn, class Watch>
void parallel_for_watched(int n, int threads, WatchBeat& beat, Fn&& fn, Watch&& watch) {
  detail::WorkQueue<Fn> q(n, fn);
  const int count = std::max(1, std::min(threads, n));
  std::mutex m;
  std::condition_variable finished;
  int running = count;
  std::vector<std::thread> pool;
  pool.reserve(std::size_t(count));
  for (int t = 0; t < count; ++t)
    pool.emplace_back([&] {
      q.run();
      std::lock_guard lock(m);
      if (--running == 0) finished.notify_one();
    });
  std::exception_ptr watch_error;
  const auto done = [&] { return running == 0; };
  for (std::unique_lock lock(m); !done();) {
    if (watch_error) {
      finished.wait(lock, done);
      break;
    }
    if (finished.wait_until(lock, beat.due, done)) break;
    lock.unlock();
    try {
      watch();
    } catch (...) {
      watch_error = std::current_exception();
    }
    beat.due = std::max(beat.due + beat.period, WatchBeat::Clock::now());
    lock.lock();
  }
  for (auto& t : pool) t.join();
  if (q.error) std::rethrow_exception(q.error);
  if (watch_error) std::rethrow_exception(watch_error);
}

}  // namespace sn::io
