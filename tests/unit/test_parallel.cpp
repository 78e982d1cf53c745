// io::parallel_for and io::parallel_for_watched: every index once, on the threads asked for.
#include "io/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace sn::io;

// The caller watches on its own thread while the work runs elsewhere; a throwing watch() is
// not called again, the work still finishes, then its exception comes out.
TEST(ParallelForWatched, CallerWatchesWhileWorkersWork) {
  const auto caller = std::this_thread::get_id();
  std::atomic<int> done{0}, on_caller{0};
  int watches = 0;
  WatchBeat beat(0.005);
  parallel_for_watched(
      4, 2, beat,
      [&](int) {
        if (std::this_thread::get_id() == caller) ++on_caller;
        std::this_thread::sleep_for(std::chrono::milliseconds(40));
        ++done;
      },
      [&] {
        EXPECT_EQ(std::this_thread::get_id(), caller);
        ++watches;
      });
  EXPECT_EQ(done, 4);
  EXPECT_EQ(on_caller, 0);
  EXPECT_GE(watches, 5);  // 80 ms of work, a watch every 5 ms

  watches = 0;
  done = 0;
  EXPECT_THROW(parallel_for_watched(
                   2, 2, beat, [&](int) { std::this_thread::sleep_for(std::chrono::milliseconds(30)), ++done; },
                   [&] {
                     ++watches;
                     throw std::runtime_error("watch failed");
                   }),
               std::runtime_error);
  EXPECT_EQ(watches, 1);
  EXPECT_EQ(done, 2);
}

// Every index runs once, call after call, and the threads that helped one call wait for the
// next: a helper's thread-local count passes 1 only if it is the same thread (threads started
// per call would each count 1).
TEST(ParallelFor, EveryIndexOnceOnThreadsThatStay) {
  const auto caller = std::this_thread::get_id();
  std::atomic<int> most{0};
  for (int call = 0; call < 20; ++call) {
    std::vector<std::atomic<int>> hits(37);
    parallel_for(37, 3, [&](int i) {
      ++hits[size_t(i)];
      if (std::this_thread::get_id() != caller) {
        thread_local int calls_here = 0, last_call = -1;
        if (last_call != call) last_call = call, ++calls_here;
        for (int m = most; m < calls_here && !most.compare_exchange_weak(m, calls_here);) {
        }
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));  // so that the helpers get some
    });
    for (int i = 0; i < 37; ++i) ASSERT_EQ(hits[size_t(i)], 1) << "index " << i << ", call " << call;
  }
  EXPECT_GT(most, 1);
}

// A parallel_for inside another (the pool is held) starts threads of its own; an exception
// comes out of the call that threw it, and the pool works after it.
TEST(ParallelFor, NestedCallsAndExceptions) {
  std::atomic<int> inner{0}, elsewhere{0};
  parallel_for(4, 2, [&](int) {
    const auto outer = std::this_thread::get_id();
    parallel_for(5, 2, [&](int) {
      ++inner;
      if (std::this_thread::get_id() != outer) ++elsewhere;
    });
  });
  EXPECT_EQ(inner, 20);
  EXPECT_EQ(elsewhere, 0);  // the inner calls ran on their callers: the threads had the outer work
  EXPECT_THROW(parallel_for(8, 2,
                            [&](int i) {
                              if (i == 3) throw std::runtime_error("index 3");
                            }),
               std::runtime_error);
  std::atomic<int> after{0};
  parallel_for(16, 2, [&](int) { ++after; });
  EXPECT_EQ(after, 16);
}
