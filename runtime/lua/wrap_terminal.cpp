// The terminal a long script talks to: sn.isatty(), sn.terminal_width(), and a gentle Ctrl-C
// (sn.catch_interrupt([on]) / sn.interrupted(); sn.train's stop, lua/interrupt.h). Without them
// SIGINT kills the process at once; a sweep that catches it stops the training in flight at its
// next step, keeps the runs finished before, and stops; a second Ctrl-C still stops at once.
// After sn.catch_interrupt(), SIGTERM (kill's default, and what a batch scheduler such as Slurm
// sends before SIGKILL) is caught alike: a sweep killed at its time limit keeps its finished runs.
// sn.train alone catches only Ctrl-C (a script that does not ask would go on after a SIGTERM).
#include <csignal>
#include <cstdio>
#include <sys/ioctl.h>
#include <unistd.h>

#include "lua/binding.h"
#include "lua/interrupt.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

volatile std::sig_atomic_t g_interrupts = 0;
volatile std::sig_atomic_t g_first_signal = 0;  // SIGINT or SIGTERM: the one that stopped the work
bool g_catching = false;  // between sn.catch_interrupt() and sn.catch_interrupt(false)
// The running sn.train's stop flag, or nullptr. A pointer atomic is lock-free on every platform
// we build on, so the handler may read it.
std::atomic<std::atomic<bool>*> g_train_stop{nullptr};
// Live mode (LiveInterrupt): a run is in progress, and a Ctrl-C it has not taken yet.
volatile std::sig_atomic_t g_live = 0, g_live_pending = 0;
static_assert(std::atomic<std::atomic<bool>*>::is_always_lock_free && std::atomic<bool>::is_always_lock_free,
              "the SIGINT handler needs lock-free atomics");

void say(const char* msg, std::size_t n) {
  ssize_t ignored = write(STDERR_FILENO, msg, n);
  (void)ignored;
}

extern "C" void on_sigint(int signo) {
  if (g_live && signo == SIGINT) {
    if (g_live_pending) {  // the first has not stopped the work: this one ends the process now
      std::signal(SIGINT, SIG_DFL);
      std::raise(SIGINT);
      return;
    }
    g_live_pending = 1;
    static const char msg[] = "\n[live] interrupt: stopping the script (Ctrl-C again to end shadenet at once)\n";
    say(msg, sizeof msg - 1);
    return;
  }
  if (g_interrupts == 0) g_first_signal = signo;
  g_interrupts = g_interrupts + 1;
  // The second signal gets the default action back: the process ends now.
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (signo == SIGTERM) {
    static const char msg[] = "\nterminate (SIGTERM): ";
    say(msg, sizeof msg - 1);
  } else {
    static const char msg[] = "\ninterrupt: ";
    say(msg, sizeof msg - 1);
  }
  if (std::atomic<bool>* stop = g_train_stop.load()) {
    stop->store(true);
    static const char msg[] = "stopping training at the next step (Ctrl-C again to stop now)\n";
    say(msg, sizeof msg - 1);
  } else {
    static const char msg[] = "finishing the work in flight, then stopping (Ctrl-C again to stop now)\n";
    say(msg, sizeof msg - 1);
  }
}

void set_handler(void (*handler)(int), bool and_sigterm) {
  struct sigaction sa {};
  sa.sa_handler = handler;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(SIGINT, &sa, nullptr);
  if (and_sigterm) sigaction(SIGTERM, &sa, nullptr);
}

void (*current_handler())(int) {
  struct sigaction sa {};
  sigaction(SIGINT, nullptr, &sa);
  return (sa.sa_flags & SA_SIGINFO) ? nullptr : sa.sa_handler;
}

}  // namespace

TrainInterrupt::TrainInterrupt(std::atomic<bool>* stop) : previous_(g_train_stop.exchange(stop)) {
  // Under sn.catch_interrupt(), a Ctrl-C counted before this training began (while a sweep built
  // its dataset) stops it at once: it trained the whole group. The handler is the default again,
  // so the next one ends the process, as promised. Without it (a script's own sn.train, live
  // mode) a past Ctrl-C stopped that training only: every later one trained 0 steps.
  if (g_catching && g_interrupts > 0) {
    stop->store(true);
    return;
  }
  if (current_handler() == SIG_DFL) {
    set_handler(on_sigint, false);
    installed_ = true;
  }
}

TrainInterrupt::~TrainInterrupt() {
  g_train_stop.store(previous_);
  // Still ours and not fired: the default action back, as before sn.train.
  if (installed_ && current_handler() == on_sigint) set_handler(SIG_DFL, false);
}

LiveInterrupt::LiveInterrupt() {
  // Nested (a frame drawn inside a run) or under sn.catch_interrupt(): the handler is in place.
  if (g_live || current_handler() == on_sigint) return;
  g_live_pending = 0;
  // An ignored SIGINT (a background job) stays ignored.
  if (current_handler() != SIG_DFL) return;
  set_handler(on_sigint, false);
  installed_ = true;
  g_live = 1;
}

LiveInterrupt::~LiveInterrupt() {
  if (!installed_) return;
  g_live = 0;
  g_live_pending = 0;
  if (current_handler() == on_sigint) set_handler(SIG_DFL, false);
}

bool LiveInterrupt::take() {
  if (!g_live_pending) return false;
  g_live_pending = 0;
  return true;
}

namespace {

int stream_fd(lua_State* L, int idx) {
  if (lua_isnoneornil(L, idx)) return STDOUT_FILENO;
  std::string s = check_string(L, idx, "sn.isatty stream");
  return check_choice(s, {"stdin", "stdout", "stderr"}, "stream");
}

// sn.isatty([stream = "stdout"]) -> true when the stream is a terminal ("stdin", "stdout", "stderr")
int w_isatty(lua_State* L) {
  lua_pushboolean(L, isatty(stream_fd(L, 1)) == 1);
  return 1;
}

// sn.terminal_width() -> columns of the terminal on stdout, or nil when it is not one
int w_terminal_width(lua_State* L) {
  winsize ws{};
  if (isatty(STDOUT_FILENO) != 1 || ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) != 0 || ws.ws_col == 0) {
    lua_pushnil(L);
  } else {
    lua_pushinteger(L, ws.ws_col);
  }
  return 1;
}

// sn.catch_interrupt([on = true]): from now on the first Ctrl-C only sets a flag (see
// sn.interrupted()); sn.catch_interrupt(false) gives Ctrl-C its default action back (stop now).
int w_catch_interrupt(lua_State* L) {
  // A boolean: "no" and 0 are true in Lua, and turned catching on.
  const bool on = lua_isnoneornil(L, 1) ? true : check_boolean(L, 1, "sn.catch_interrupt argument 1");
  g_catching = on;
  if (on) {
    g_interrupts = 0;
    set_handler(on_sigint, true);
  } else {
    set_handler(SIG_DFL, true);
  }
  return 0;
}

// sn.interrupted() -> true once a Ctrl-C was caught (by sn.catch_interrupt() or a running
// sn.train) since the last sn.catch_interrupt(), and the signal's number (2 SIGINT, 15 SIGTERM):
// a script that stops for it exits 128 + that number, as the shell reports a process it killed.
int w_interrupted(lua_State* L) {
  lua_pushboolean(L, g_interrupts > 0);
  if (g_interrupts == 0) return 1;
  lua_pushinteger(L, g_first_signal);
  return 2;
}

}  // namespace

void open_terminal(lua_State* L) {
  static const luaL_Reg fns[] = {SN_FN("isatty", w_isatty), SN_FN("terminal_width", w_terminal_width),
                                 SN_FN("catch_interrupt", w_catch_interrupt),
                                 SN_FN("interrupted", w_interrupted), {nullptr, nullptr}};
  luaL_register(L, nullptr, fns);
}

}  // namespace sn::lua
