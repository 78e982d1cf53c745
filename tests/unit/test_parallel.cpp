// io::parallel_for and io::parallel_for_watched: every index once, on the threads asked for.
#include "io/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

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
