// Ctrl-C for the whole process, one SIGINT handler (wrap_terminal.cpp) for both of its users:
// sn.catch_interrupt() (a sweep's flag, sn.interrupted()) and sn.train, which stops at the next
// step boundary. Whichever of them caught it, the first Ctrl-C gives SIGINT its default action
// back: the second ends the process (exit status 130 in a shell).
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

}  // namespace sn::lua
