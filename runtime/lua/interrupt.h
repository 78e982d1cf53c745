// Ctrl-C for the whole process, one SIGINT handler (wrap_terminal.cpp) for its three users:
// sn.catch_interrupt() (a sweep's flag, sn.interrupted()), sn.train, which stops at the next
// step boundary, and live mode's runs (LiveInterrupt). For the first two the first Ctrl-C gives
// SIGINT its default action back: the second ends the process (exit status 130 in a shell).
#pragma once
#include <atomic>

namespace sn::lua {

// While one lives, the first Ctrl-C sets `stop` (a job's stop flag, nn/train.h) besides the
// count sn.interrupted() reads. It installs the handler only where SIGINT has its default
// action (an ignored SIGINT, as in a background job, stays ignored) and puts the default back
// when it ends, unless sn.catch_interrupt() was on before it.
class TrainInterrupt {
 public:
  explicit TrainInterrupt(std::atomic<bool>* stop);
  ~TrainInterrupt();
  TrainInterrupt(const TrainInterrupt&) = delete;
  TrainInterrupt& operator=(const TrainInterrupt&) = delete;

 private:
  std::atomic<bool>* previous_;
  bool installed_ = false;
};

// While one lives (a live session runs its script, a console line or a frame), each Ctrl-C only
// sets a flag that take() reads and clears: the live loop turns it into a Lua error and the
// session goes on. A second Ctrl-C before the first was taken (the work is stuck in a long C
// call) ends the process, as does a Ctrl-C while none lives. A TrainInterrupt inside it leaves
// the handler alone: live mode stops its training through the training's tick.
class LiveInterrupt {
 public:
  LiveInterrupt();  // clears a flag left from before
  ~LiveInterrupt();
  LiveInterrupt(const LiveInterrupt&) = delete;
  LiveInterrupt& operator=(const LiveInterrupt&) = delete;
  static bool take();  // true once per Ctrl-C caught

 private:
  bool installed_ = false;
};

}  // namespace sn::lua
